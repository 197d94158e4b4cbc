#pragma once

#include <QString>
#include <optional>

namespace dd {

// Outcome of decoding one frame: a value, or a specific reason it was rejected.
template <typename T>
struct Decoded
{
    std::optional<T> value;
    QString error; // English, technical (for traces and exceptions); empty when value is set

    bool ok() const { return value.has_value(); }
    static Decoded success(T v)
    {
        Decoded d;
        d.value = std::move(v);
        return d;
    }
    static Decoded failure(QString why)
    {
        Decoded d;
        d.error = std::move(why);
        return d;
    }
};

} // namespace dd

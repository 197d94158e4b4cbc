#pragma once

#include <QByteArray>

namespace dd::test {

// Bytes from hex text: hex("01 03 00") or hex("010300").
inline QByteArray hex(const char *h)
{
    return QByteArray::fromHex(h);
}

} // namespace dd::test

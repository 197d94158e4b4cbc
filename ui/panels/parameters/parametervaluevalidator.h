#pragma once

#include "core/common/error.h"

#include <QValidator>

namespace dd {

class ParameterDictionary;

// The check every edited parameter value passes before it may be sent: the text is a whole
// number (decimal, or hexadecimal with 0x) and ParameterDictionary::validateWrite() accepts
// it (known parameter, inside its range, not read-only). As a QValidator on the editor it
// answers Intermediate, never Invalid, for a value that fails, so the user can go on typing
// while reason() says what is wrong; the editor cannot be committed until it is Acceptable.
class ParameterValueValidator : public QValidator
{
    Q_OBJECT
public:
    ParameterValueValidator(const ParameterDictionary *dictionary, int parameterIndex, QObject *parent = nullptr);

    State validate(QString &input, int &pos) const override;
    // The translated reason `text` is refused; empty when it is acceptable.
    QString reason(const QString &text) const;

    // Parses and validates `text` for parameter `index`; on success *value is set.
    static Error check(const ParameterDictionary &dictionary, int index, const QString &text, qint64 *value);
    // A whole number: optional sign, decimal digits, or 0x and hexadecimal digits.
    static bool parseValue(const QString &text, qint64 *value);

private:
    const ParameterDictionary *m_dictionary = nullptr;
    int m_index = -1;
};

} // namespace dd

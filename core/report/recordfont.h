#pragma once

#include <QFont>
#include <QLocale>
#include <QString>

namespace dd {

// The font a commissioning record is set in. Latin text uses the system's sans-serif font;
// a record in Chinese needs a CJK font, which the PDF embeds (as a subset) so that the file
// shows and searches the same on any computer. Noto Sans CJK (Debian: fonts-noto-cjk) is
// preferred, then other common CJK families. When the system has none, the record is still
// made, but Chinese characters cannot be drawn: cjkFamily() is empty and the tools say so
// (docs/record.md).
class RecordFont
{
public:
    // Needs a QGuiApplication.
    static QFont font(const QLocale &locale, qreal pointSize);
    // The CJK family in use, "" when the system has none.
    static QString cjkFamily();
    // Whether text in `locale` needs a CJK font.
    static bool needsCjk(const QLocale &locale);
};

} // namespace dd

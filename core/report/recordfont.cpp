#include "core/report/recordfont.h"

#include <QFontDatabase>
#include <QStringList>

namespace dd {

QString RecordFont::cjkFamily()
{
    static const QString chosen = [] {
        const QStringList preferred = {QStringLiteral("Noto Sans CJK SC"),  QStringLiteral("Source Han Sans SC"),
                                       QStringLiteral("Noto Sans SC"),      QStringLiteral("WenQuanYi Micro Hei"),
                                       QStringLiteral("WenQuanYi Zen Hei"), QStringLiteral("Droid Sans Fallback"),
                                       QStringLiteral("AR PL UMing CN"),    QStringLiteral("Noto Serif CJK SC")};
        const QStringList families = QFontDatabase::families(QFontDatabase::SimplifiedChinese);
        for (const QString &p : preferred)
            for (const QString &f : families)
                if (f.compare(p, Qt::CaseInsensitive) == 0)
                    return f;
        return families.isEmpty() ? QString() : families.first();
    }();
    return chosen;
}

bool RecordFont::needsCjk(const QLocale &locale)
{
    return locale.language() == QLocale::Chinese || locale.language() == QLocale::Japanese
        || locale.language() == QLocale::Korean;
}

QFont RecordFont::font(const QLocale &locale, qreal pointSize)
{
    // Latin first, the CJK family after it for the characters the Latin fonts lack. Not the
    // other way round: Qt 6.4's PDF writer maps Noto CJK's digits to no text (they print,
    // but a search or pdftotext finds blanks), while DejaVu's map as they should.
    QStringList families{QStringLiteral("DejaVu Sans"), QStringLiteral("Liberation Sans"), QStringLiteral("Noto Sans")};
    const QString cjk = cjkFamily();
    if (!cjk.isEmpty())
        families << cjk;
    Q_UNUSED(locale)
    QFont f;
    f.setFamilies(families);
    f.setStyleHint(QFont::SansSerif);
    f.setPointSizeF(pointSize);
    // Qt 6.4 has no switch for OpenType features: any letter spacing turns ligatures off,
    // so that "ff" in a checksum stays two letters for the reader and for text extraction.
    f.setLetterSpacing(QFont::AbsoluteSpacing, 0.05); // the smallest step Qt keeps (1/64)
    return f;
}

} // namespace dd

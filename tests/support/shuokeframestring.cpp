#include "tests/support/shuokeframestring.h"

#include <QByteArray>
#include <QString>

namespace dd::shuoke {

char *toString(const Frame &f)
{
    const QByteArray s = QStringLiteral("Frame(addr %1 cmd 0x%2 %3)")
                             .arg(f.address)
                             .arg(f.command, 2, 16, QLatin1Char('0'))
                             .arg(f.failure ? QStringLiteral("failure %1").arg(f.failureCode)
                                            : QString::fromLatin1(f.data.toHex(' ')))
                             .toLatin1();
    return qstrdup(s.constData());
}

} // namespace dd::shuoke

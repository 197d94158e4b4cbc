#include "tests/support/trendsamplestring.h"

namespace QTest {

template <>
char *toString(const dd::TrendSample &s)
{
    return QTest::toString(QStringLiteral("(%1 us, %2)").arg(s.timeUs).arg(s.value));
}

} // namespace QTest

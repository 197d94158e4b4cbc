#pragma once

#include "core/trend/trendsample.h"

#include <QtTest>

namespace QTest {

// How QCOMPARE shows a TrendSample: "(1000 us, 2.5)".
template <>
char *toString(const dd::TrendSample &s);

} // namespace QTest

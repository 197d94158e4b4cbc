#pragma once

#include <QtTest>

// A test that needs a third-party tool (mbpoll, canbusutil, libmodbus, Qt's virtualcan
// plugin, pseudo-terminals) skips when it is missing on a developer's machine, but fails
// where the tools are promised: CI installs every one of them (packaging/install-deps.sh)
// and packaging/test.sh sets DRIVEDESK_REQUIRE_TOOLS=1, so that a missing tool can never
// pass for a green run.
namespace dd::test {

inline bool toolsRequired()
{
    return qEnvironmentVariableIntValue("DRIVEDESK_REQUIRE_TOOLS") != 0;
}

} // namespace dd::test

#define DD_REQUIRE_TOOL(available, why)                                                                                \
    do {                                                                                                               \
        if (!(available)) {                                                                                            \
            if (dd::test::toolsRequired())                                                                             \
                QFAIL(qPrintable(QStringLiteral("%1 (DRIVEDESK_REQUIRE_TOOLS is set: CI installs it)")                 \
                                     .arg(QString::fromUtf8(why))));                                                   \
            QSKIP(why);                                                                                                \
        }                                                                                                              \
    } while (false)

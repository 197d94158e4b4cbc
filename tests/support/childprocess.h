#pragma once

#include <QProcess>

#include <csignal>
#include <sys/prctl.h>

namespace dd::test {

// A helper process (a peer, socat) dies with the test: a test that aborts (a sanitizer
// report) must not leave it holding ctest's output pipe open until ctest's timeout.
inline void dieWithParent(QProcess &p)
{
    p.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGKILL); });
}

} // namespace dd::test

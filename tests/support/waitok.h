#pragma once

#include "core/drive/drivereply.h"
#include "tests/support/replywait.h"

#include <QtTest>

// Waits for the DriveReply `reply` (up to 8 s) and fails the test unless it finished
// without an error (the error's message is shown).
#define WAIT_OK(reply)                                                                                                 \
    do {                                                                                                               \
        dd::DriveReply *r_ = (reply);                                                                                  \
        QVERIFY2(dd::test::waitForReply(r_, 8000), "no answer in time");                                               \
        QVERIFY2(r_->ok(), qPrintable(r_->error().message));                                                           \
    } while (false)

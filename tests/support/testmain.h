#pragma once

// Makes a test file's main() an entry of its test program (tests/CMakeLists.txt: the files of
// one folder share one program, which runs the file named by its first argument).
//
// Included before every test file (the test program's precompiled header, or -include): after
// QtTest's own definitions, QTEST_MAIN, QTEST_GUILESS_MAIN and QTEST_APPLESS_MAIN define
// `int drivedesk_test_<TestClass>(int argc, char **argv)` instead of main(), with the same
// body as QtTest's (the application object each asks for, initMain(), the source path for
// QFINDTESTDATA). A file that needs its own main() writes DRIVEDESK_TEST_MAIN(TestClass) { ... }
// instead. The generated main() finds the entry by the class named in that line.
#include <QtTest/QtTest>

#define DRIVEDESK_TEST_MAIN(TestObject) int drivedesk_test_##TestObject(int argc, char **argv)

#undef QTEST_MAIN_WRAPPER
#define QTEST_MAIN_WRAPPER(TestObject, ...)                                                                            \
    DRIVEDESK_TEST_MAIN(TestObject)                                                                                    \
    {                                                                                                                  \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>();                                             \
        __VA_ARGS__                                                                                                    \
        TestObject tc;                                                                                                 \
        QTEST_SET_MAIN_SOURCE_PATH                                                                                     \
        return QTest::qExec(&tc, argc, argv);                                                                          \
    }

// preferPlainEventDispatcher() (core/common/eventdispatcherchoice.h): the programs' threads
// get Qt's plain poll() dispatcher, not GLib's; a QT_NO_GLIB the user set is left alone.
#include <QtTest>

#include "core/common/eventdispatcherchoice.h"

#include <QAbstractEventDispatcher>
#include <QThread>

namespace {
bool g_setAtStart = false; // what the test's main saw, before the application object existed
}

class TestEventDispatcherChoice : public QObject
{
    Q_OBJECT

private slots:
    void mainThreadGetsThePlainDispatcher();
    void threadsGetThePlainDispatcher();
    void leavesAUserChoiceAlone();
};

void TestEventDispatcherChoice::mainThreadGetsThePlainDispatcher()
{
#if !defined(Q_OS_UNIX) || defined(Q_OS_DARWIN)
    QSKIP("GLib's dispatcher is a Linux/Unix choice");
#else
    QVERIFY(g_setAtStart);
    QCOMPARE(qgetenv("QT_NO_GLIB"), QByteArray("1"));
    QVERIFY(QCoreApplication::eventDispatcher());
    QCOMPARE(QCoreApplication::eventDispatcher()->metaObject()->className(), "QEventDispatcherUNIX");
#endif
}

void TestEventDispatcherChoice::threadsGetThePlainDispatcher()
{
#if !defined(Q_OS_UNIX) || defined(Q_OS_DARWIN)
    QSKIP("GLib's dispatcher is a Linux/Unix choice");
#else
    QThread thread;
    thread.start();
    QObject probe;
    probe.moveToThread(&thread);
    QByteArray name;
    QMetaObject::invokeMethod(
        &probe, [&name] { name = QAbstractEventDispatcher::instance()->metaObject()->className(); },
        Qt::BlockingQueuedConnection);
    thread.quit();
    QVERIFY(thread.wait(5000));
    QCOMPARE(name, QByteArray("QEventDispatcherUNIX"));
#endif
}

void TestEventDispatcherChoice::leavesAUserChoiceAlone()
{
    const QByteArray saved = qgetenv("QT_NO_GLIB");
    qputenv("QT_NO_GLIB", ""); // set and empty: the user keeps GLib's dispatcher
    QVERIFY(!dd::preferPlainEventDispatcher());
    QVERIFY(qEnvironmentVariableIsSet("QT_NO_GLIB"));
    QCOMPARE(qgetenv("QT_NO_GLIB"), QByteArray());
    qputenv("QT_NO_GLIB", saved);
}

// Its own main() (tests/support/testmain.h): the variable is unset before the application object
// exists.
DRIVEDESK_TEST_MAIN(TestEventDispatcherChoice)
{
    // As the programs do, from an environment without the variable (ctest sets it for the
    // other tests).
    qunsetenv("QT_NO_GLIB");
    g_setAtStart = dd::preferPlainEventDispatcher();
    QCoreApplication app(argc, argv);
    TestEventDispatcherChoice t;
    return QTest::qExec(&t, argc, argv);
}

#include "tst_eventdispatcherchoice.moc"

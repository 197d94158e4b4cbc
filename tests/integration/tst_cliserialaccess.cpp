// A serial port the user may not open: drivedesk-cli says exactly what to do (join the
// port's group, then log in again), on both serial links (Modbus for servo-modbus, the raw
// serial link for shuoke). The port is a pty handed to group dialout with mode 0660; the CLI
// runs as the user nobody. Root bypasses file modes, so the child drops to nobody before it
// runs: the test needs root (as in CI) and is skipped otherwise.
#include "tests/support/clirun.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace dd::test;

class TestCliSerialAccess : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void deniedPortSaysWhatToDo_data();
    void deniedPortSaysWhatToDo();
    void deniedPortAsJson();

private:
    CliRun runAsNobody(const QStringList &arguments);

    int m_master = -1;
    QString m_slave;
    uid_t m_nobodyUid = 0;
    gid_t m_nobodyGid = 0;
    QTemporaryDir m_dir;
    QString m_cli;
};

void TestCliSerialAccess::initTestCase()
{
    if (::geteuid() != 0)
        QSKIP("needs root: the pty is handed to group dialout and the CLI runs as nobody (CI runs as root)");
    const struct passwd *nobody = ::getpwnam("nobody");
    const struct group *dialout = ::getgrnam("dialout");
    QVERIFY2(nobody, "no user nobody");
    QVERIFY2(dialout, "no group dialout");
    m_nobodyUid = nobody->pw_uid;
    m_nobodyGid = nobody->pw_gid;

    m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
    QVERIFY(m_master >= 0);
    QCOMPARE(::grantpt(m_master), 0);
    QCOMPARE(::unlockpt(m_master), 0);
    m_slave = QString::fromLocal8Bit(::ptsname(m_master));
    const QByteArray slave = QFile::encodeName(m_slave);
    QCOMPARE(::chown(slave.constData(), 0, dialout->gr_gid), 0);
    QCOMPARE(::chmod(slave.constData(), 0660), 0);

    // nobody must be able to run the CLI and write a home: both live in a world-readable
    // temporary folder (the build tree may be in root's home).
    QVERIFY(m_dir.isValid());
    QVERIFY(QFile::setPermissions(m_dir.path(),
                                  QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner
                                      | QFileDevice::ReadOther | QFileDevice::ExeOther | QFileDevice::ReadGroup
                                      | QFileDevice::ExeGroup));
    m_cli = m_dir.filePath(QStringLiteral("drivedesk-cli"));
    QVERIFY(QFile::copy(cliPath(), m_cli));
    QVERIFY(QDir(m_dir.path()).mkdir(QStringLiteral("home")));
    QCOMPARE(::chown(QFile::encodeName(m_dir.filePath(QStringLiteral("home"))).constData(), m_nobodyUid, m_nobodyGid),
             0);
}

void TestCliSerialAccess::cleanupTestCase()
{
    if (m_master >= 0)
        ::close(m_master);
}

CliRun TestCliSerialAccess::runAsNobody(const QStringList &arguments)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
    env.insert(QStringLiteral("LANGUAGE"), QStringLiteral("en"));
    env.insert(QStringLiteral("HOME"), m_dir.filePath(QStringLiteral("home")));
    env.insert(QStringLiteral("USER"), QStringLiteral("nobody"));
    // Sanitizer builds: nobody must be able to read LeakSanitizer's suppressions (the source
    // tree may be in root's home), so they are read from a copy.
    QString lsan = env.value(QStringLiteral("LSAN_OPTIONS"));
    const QRegularExpression supp(QStringLiteral("suppressions=([^:]+)"));
    if (const QRegularExpressionMatch m = supp.match(lsan); m.hasMatch()) {
        const QString copy = m_dir.filePath(QStringLiteral("lsan.supp"));
        if (!QFile::exists(copy))
            QFile::copy(m.captured(1), copy);
        lsan.replace(m.capturedStart(1), m.capturedLength(1), copy);
        env.insert(QStringLiteral("LSAN_OPTIONS"), lsan);
    }
    p.setProcessEnvironment(env);
    const uid_t uid = m_nobodyUid;
    const gid_t gid = m_nobodyGid;
    p.setChildProcessModifier([uid, gid] {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        // no supplementary groups (root's would include dialout on some systems)
        if (::setgroups(0, nullptr) != 0 || ::setgid(gid) != 0 || ::setuid(uid) != 0)
            ::_exit(120);
    });
    p.start(m_cli, arguments);
    CliRun r;
    r.finished = p.waitForFinished(30000);
    r.exitCode = p.exitCode();
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

void TestCliSerialAccess::deniedPortSaysWhatToDo_data()
{
    QTest::addColumn<QString>("family");
    QTest::newRow("servo-modbus (Modbus link)") << QStringLiteral("servo-modbus");
    QTest::newRow("shuoke (serial link)") << QStringLiteral("shuoke");
}

void TestCliSerialAccess::deniedPortSaysWhatToDo()
{
    QFETCH(QString, family);
    const CliRun r = runAsNobody(
        {QStringLiteral("--family"), family, QStringLiteral("--port"), m_slave, QStringLiteral("info")});
    QVERIFY2(r.finished, r.err.constData());
    QVERIFY2(r.exitCode != 120, "could not drop to the user nobody");
    QCOMPARE(r.exitCode, 3); // the port could not be opened
    const QString text = r.text();
    QVERIFY2(text.contains(
                 QStringLiteral("You may not use the serial port %1: it belongs to the group 'dialout'").arg(m_slave)),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("    sudo usermod -aG dialout $USER\n")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("log out and log in again")), qPrintable(text));
}

void TestCliSerialAccess::deniedPortAsJson()
{
    const CliRun r = runAsNobody({QStringLiteral("--json"), QStringLiteral("--port"), m_slave, QStringLiteral("info")});
    QCOMPARE(r.exitCode, 3);
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("ok")).toBool(true), false);
    const QString message = o.value(QStringLiteral("error")).toObject().value(QStringLiteral("message")).toString();
    QVERIFY2(message.contains(QStringLiteral("sudo usermod -aG dialout $USER")), r.out.constData());
}

QTEST_GUILESS_MAIN(TestCliSerialAccess)
#include "tst_cliserialaccess.moc"

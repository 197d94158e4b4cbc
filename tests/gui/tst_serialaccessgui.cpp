// "Permission denied" on a serial port in the workbench: connecting to a port this user may
// not use opens the dialog with the command that fixes it. The port is a pty handed to group
// dialout with mode 0660, and this test process drops from root to the user nobody first
// (root bypasses file modes): it needs root, as in CI, and is skipped otherwise.
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/connectrequest.h"
#include "ui/bus/serialaccessdialog.h"
#include "ui/shell/mainwindow.h"

#include <QFile>
#include <QLineEdit>
#include <QLoggingCategory>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace dd;

class TestSerialAccessGui : public QObject
{
    Q_OBJECT

    QTemporaryDir m_home;
    int m_master = -1;
    QString m_slave;

private slots:
    void initTestCase()
    {
        if (::geteuid() != 0)
            QSKIP("needs root: the pty is handed to group dialout and the test drops to nobody (CI runs as root)");
        const struct passwd *nobody = ::getpwnam("nobody");
        const struct group *dialout = ::getgrnam("dialout");
        QVERIFY2(nobody, "no user nobody");
        QVERIFY2(dialout, "no group dialout");
        const uid_t uid = nobody->pw_uid;
        const gid_t gid = nobody->pw_gid;

        m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
        QVERIFY(m_master >= 0);
        QCOMPARE(::grantpt(m_master), 0);
        QCOMPARE(::unlockpt(m_master), 0);
        m_slave = QString::fromLocal8Bit(::ptsname(m_master));
        const QByteArray slave = QFile::encodeName(m_slave);
        QCOMPARE(::chown(slave.constData(), 0, dialout->gr_gid), 0);
        QCOMPARE(::chmod(slave.constData(), 0660), 0);

        // A home and settings nobody may write, then become nobody for good.
        QVERIFY(m_home.isValid());
        QCOMPARE(::chown(QFile::encodeName(m_home.path()).constData(), uid, gid), 0);
        qputenv("HOME", QFile::encodeName(m_home.path()));
        QCOMPARE(::setgroups(0, nullptr), 0);
        QCOMPARE(::setgid(gid), 0);
        QCOMPARE(::setuid(uid), 0);
        // Changing the user makes the process non-dumpable, and LeakSanitizer (the asan
        // stage) then cannot inspect its own threads at exit.
        QCOMPARE(::prctl(PR_SET_DUMPABLE, 1), 0);
        QVERIFY(::access(slave.constData(), R_OK | W_OK) != 0);

        QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false"));
        QStandardPaths::setTestModeEnabled(true);
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_home.path());
        QCoreApplication::setOrganizationName(QStringLiteral("DriveDeskTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_serialaccessgui"));
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
    }

    void cleanupTestCase()
    {
        if (m_master >= 0)
            ::close(m_master);
    }

    void deniedPortOpensTheDialog()
    {
        MainWindow w;
        w.show();
        QSignalSpy denied(w.connections(), &ConnectionController::serialAccessDenied);
        ConnectRequest r;
        r.settings.family = Family::ServoModbus;
        r.settings.port = m_slave;
        w.connectTo(r);
        QTRY_VERIFY_WITH_TIMEOUT(w.findChild<SerialAccessDialog *>(), 10000);
        QCOMPARE(denied.size(), 1);
        auto *dialog = w.findChild<SerialAccessDialog *>();
        QVERIFY(dialog->isVisible());
        QCOMPARE(dialog->problem().port, m_slave);
        QCOMPARE(dialog->problem().group, QStringLiteral("dialout"));
        auto *command = dialog->findChild<QLineEdit *>(QStringLiteral("serialAccessCommand"));
        QVERIFY(command);
        QCOMPARE(command->text(), QStringLiteral("sudo usermod -aG dialout $USER"));
        QVERIFY(dialog->copyButton()->isVisible());
    }
};

QTEST_MAIN(TestSerialAccessGui)
#include "tst_serialaccessgui.moc"

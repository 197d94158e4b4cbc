// The connect dialog: serial ports appear and vanish while it is open (a pty stands in for
// a USB adapter), CAN plugins and interfaces are listed, settings round-trip and persist,
// and "detect" tries the families in the documented order.
#include "sim/bus/ptyendpoint.h"
#include "tests/support/requiretool.h"
#include "ui/bus/connectdialog.h"
#include "ui/bus/serialportwatcher.h"

#include <QApplication>
#include <QCanBus>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace dd;

class TestConnectDialog : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;

    static bool waitForPort(SerialPortWatcher *w, const QString &path, bool present, int timeoutMs)
    {
        QSignalSpy spy(w, &SerialPortWatcher::portsChanged);
        QDeadlineTimer deadline(timeoutMs);
        while (w->contains(path) != present && !deadline.hasExpired())
            spy.wait(int(qMax<qint64>(1, deadline.remainingTime())));
        return w->contains(path) == present;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_settingsDir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("DriveDeskTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_connectdialog"));
    }

    void listsPtyAfterHotPlug()
    {
        DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this system");
        ConnectDialog dialog;
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QVERIFY(dialog.portWatcher()->isRunning());
        QVERIFY(dialog.portWatcher()->virtualPortDirectories().contains(QDir::tempPath()));

        // "Plug in" an adapter while the dialog is open: a pty with a link in the temp dir.
        const QString link = QDir(QDir::tempPath())
                                 .filePath(
                                     QStringLiteral("dd-tst-connectdialog-%1").arg(QCoreApplication::applicationPid()));
        QVERIFY(dialog.portCombo()->findData(link) < 0);
        PtyEndpoint pty;
        const Error e = pty.open(link);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(pty.clientPath(), link);
        QVERIFY(waitForPort(dialog.portWatcher(), link, true, 3 * SerialPortWatcher::PollIntervalMs));
        const int row = dialog.portCombo()->findData(link);
        QVERIFY(row >= 0);
        QVERIFY(dialog.portCombo()->itemText(row).contains(pty.slavePath()));
        // Choosing it makes it the request's port (the path, not the label).
        dialog.portCombo()->setCurrentIndex(row);
        QCOMPARE(dialog.request().settings.port, link);

        // "Unplug" it: it disappears on the next poll.
        pty.close();
        QVERIFY(!QFileInfo::exists(link));
        QVERIFY(waitForPort(dialog.portWatcher(), link, false, 3 * SerialPortWatcher::PollIntervalMs));
        QVERIFY(dialog.portCombo()->findData(link) < 0);

        // No polling while the dialog is closed.
        dialog.hide();
        QVERIFY(!dialog.portWatcher()->isRunning());
    }

    void listsCanPluginsAndInterfaces()
    {
        DD_REQUIRE_TOOL(QCanBus::instance()->plugins().contains(QLatin1String("virtualcan")),
                        "Qt's virtualcan plugin is not installed");
        ConnectDialog dialog;
        ConnectRequest r;
        r.settings.can = QStringLiteral("virtualcan:can1");
        dialog.setRequest(r);
        auto *plugin = dialog.findChild<QComboBox *>(QStringLiteral("canPluginCombo"));
        QVERIFY(plugin);
        QCOMPARE(plugin->currentText(), QStringLiteral("virtualcan"));
        auto *iface = dialog.findChild<QComboBox *>(QStringLiteral("canInterfaceCombo"));
        QVERIFY(iface->findData(QStringLiteral("can0")) >= 0); // virtualcan offers can0 and can1
        QCOMPARE(dialog.request().settings.can, QStringLiteral("virtualcan:can1"));
        QVERIFY(dialog.request().settings.isCan());
    }

    void requestRoundTripsAndPersists()
    {
        ConnectRequest r;
        r.settings.port = QStringLiteral("/dev/ttyUSB7");
        r.settings.family = Family::Shuoke;
        r.settings.framing = QStringLiteral("ascii");
        r.settings.baud = 38400;
        r.detect = false;
        r.scan = true;
        r.scanOptions.from = 3;
        r.scanOptions.to = 40;
        r.sweepBauds = true;
        r.scanOptions.timeoutMs = 80;
        {
            ConnectDialog dialog;
            dialog.setRequest(r);
            const ConnectRequest back = dialog.request();
            QCOMPARE(back.settings.port, r.settings.port);
            QCOMPARE(back.settings.family, Family::Shuoke);
            QCOMPARE(back.settings.framing, QStringLiteral("ascii"));
            QCOMPARE(back.settings.baud, 38400);
            QCOMPARE(back.detect, false);
            QCOMPARE(back.scanOptions.from, 3);
            QCOMPARE(back.scanOptions.to, 40);
            QVERIFY(back.sweepBauds);
            QCOMPARE(back.scanOptions.timeoutMs, 80);
            dialog.saveSettings();
        }
        ConnectDialog fresh;
        fresh.loadSettings();
        const ConnectRequest loaded = fresh.request();
        QCOMPARE(loaded.settings.port, r.settings.port);
        QCOMPARE(loaded.settings.family, Family::Shuoke);
        QCOMPARE(loaded.settings.framing, QStringLiteral("ascii"));
        QCOMPARE(loaded.scanOptions.to, 40);
        QCOMPARE(loaded.scanOptions.timeoutMs, 80);

        // "Automatic" is the scanners' adaptive timeout.
        ConnectRequest adaptive = r;
        adaptive.scanOptions.timeoutMs = -1;
        fresh.setRequest(adaptive);
        QCOMPARE(fresh.request().scanOptions.timeoutMs, -1);
        // A new request starts from the safe default, not from the adaptive one.
        QCOMPARE(ConnectRequest().scanOptions.timeoutMs, ConnectRequest::DefaultProbeTimeoutMs);

        // Framing is a shuoke setting only.
        ConnectRequest modbus = r;
        modbus.settings.family = Family::ServoModbus;
        fresh.setRequest(modbus);
        QVERIFY(fresh.request().settings.framing.isEmpty());
    }

    void detectOrder()
    {
        ConnectRequest serial;
        serial.detect = true;
        serial.settings.port = QStringLiteral("/dev/ttyUSB0");
        const QList<ConnectionSettings> s = serial.attempts();
        QCOMPARE(s.size(), 3);
        QCOMPARE(s.at(0).family, Family::ServoModbus);
        QCOMPARE(s.at(1).family, Family::Shuoke);
        QCOMPARE(s.at(1).framing, QStringLiteral("rtu"));
        QCOMPARE(s.at(2).framing, QStringLiteral("ascii"));
        for (const ConnectionSettings &a : s)
            QCOMPARE(a.port, serial.settings.port);

        ConnectRequest can;
        can.detect = true;
        can.settings.can = QStringLiteral("socketcan:can0");
        const QList<ConnectionSettings> c = can.attempts();
        QCOMPARE(c.size(), 2);
        QCOMPARE(c.at(0).family, Family::ServoCan);
        QCOMPARE(c.at(1).family, Family::Shuoke);
        QCOMPARE(c.at(1).framing, QStringLiteral("can"));

        can.detect = false;
        can.settings.family = Family::ServoCan;
        QCOMPARE(can.attempts().size(), 1);
    }

    void commandLineRequests()
    {
        ConnectRequest r;
        QString error;
        QVERIFY(ConnectRequest::fromCommandLine(QStringLiteral("/dev/ttyUSB0"), QString(), 19200, 0, QString(), &r,
                                                &error));
        QCOMPARE(r.settings.port, QStringLiteral("/dev/ttyUSB0"));
        QVERIFY(!r.settings.isCan());
        QVERIFY(r.detect);
        QCOMPARE(r.settings.baud, 19200);
        QVERIFY(r.scan);

        QVERIFY(ConnectRequest::fromCommandLine(QStringLiteral("COM3"), QStringLiteral("shuoke"), 0, 0,
                                                QStringLiteral("ascii"), &r, &error));
        QCOMPARE(r.settings.port, QStringLiteral("COM3"));
        QVERIFY(!r.detect);
        QCOMPARE(r.settings.family, Family::Shuoke);
        QCOMPARE(r.settings.framing, QStringLiteral("ascii"));

        if (QCanBus::instance()->plugins().contains(QLatin1String("virtualcan"))) {
            QVERIFY(ConnectRequest::fromCommandLine(QStringLiteral("virtualcan:tcp://127.0.0.1:1234/can0"),
                                                    QStringLiteral("servo-can"), 0, 500000, QString(), &r, &error));
            QVERIFY(r.settings.isCan());
            QCOMPARE(r.settings.can, QStringLiteral("virtualcan:tcp://127.0.0.1:1234/can0"));
            QCOMPARE(r.settings.bitrate, 500000);
        }
        // A Windows-style or unknown "x:" prefix is a serial port, not a CAN plugin.
        QVERIFY(ConnectRequest::fromCommandLine(QStringLiteral("nosuchplugin:can0"), QString(), 0, 0, QString(), &r,
                                                &error));
        QVERIFY(!r.settings.isCan());

        QVERIFY(!ConnectRequest::fromCommandLine(QStringLiteral("/dev/ttyS0"), QStringLiteral("stepper"), 0, 0,
                                                 QString(), &r, &error));
        QVERIFY(error.contains(QLatin1String("stepper")));
        QVERIFY(!ConnectRequest::fromCommandLine(QStringLiteral("/dev/ttyS0"), QStringLiteral("shuoke"), 0, 0,
                                                 QStringLiteral("binary"), &r, &error));
        QVERIFY(error.contains(QLatin1String("binary")));
    }

    void portLabelShowsUsbIds()
    {
        SerialPortEntry e;
        e.path = QStringLiteral("/dev/ttyUSB0");
        e.description = QStringLiteral("FT232R USB UART");
        e.manufacturer = QStringLiteral("FTDI");
        e.hasIds = true;
        e.vendorId = 0x0403;
        e.productId = 0x6001;
        QCOMPARE(e.label(), QStringLiteral("/dev/ttyUSB0 — FT232R USB UART (FTDI) [0403:6001]"));
    }
};

QTEST_MAIN(TestConnectDialog)
#include "tst_connectdialog.moc"

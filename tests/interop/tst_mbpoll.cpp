// Interop: the simulator's servo-modbus drive answers mbpoll (Debian package, a Modbus
// master built on libmodbus) over a pty. mbpoll's -r is 1-based: -r 101 is register 0x0064
// (PA0), -r 1 is 0x0000 (DP-SPd).

#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/support/requiretool.h"

#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QtTest>
#include <memory>

using namespace dd;

namespace {
constexpr int MbpollAddress = 5;
constexpr int MbpollBaud = 19200;
} // namespace

class TestMbpoll : public QObject
{
    Q_OBJECT

    QString m_mbpoll;
    SimSerialBus *m_bus = nullptr;
    PtyEndpoint *m_pty = nullptr;
    SimServoModbusDrive *m_drive = nullptr;

    // Runs mbpoll with the common RTU options plus `args`, with the event loop running (the
    // simulator lives in this process). Returns its stdout; *exitCode gets its exit code.
    QString mbpoll(const QStringList &args, int *exitCode)
    {
        QProcess p;
        QStringList all{QStringLiteral("-m"),           QStringLiteral("rtu"),  QStringLiteral("-a"),
                        QString::number(MbpollAddress), QStringLiteral("-b"),   QString::number(MbpollBaud),
                        QStringLiteral("-P"),           QStringLiteral("none"), QStringLiteral("-1")};
        all += args;
        p.start(m_mbpoll, all);
        if (!p.waitForStarted(5000))
            return QString();
        QEventLoop loop;
        QTimer guard;
        guard.setSingleShot(true);
        connect(&guard, &QTimer::timeout, &loop, &QEventLoop::quit);
        connect(&p, &QProcess::finished, &loop, &QEventLoop::quit);
        guard.start(15000);
        loop.exec();
        if (p.state() != QProcess::NotRunning) {
            p.kill();
            p.waitForFinished(2000);
        }
        *exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
        return QString::fromLocal8Bit(p.readAllStandardOutput() + p.readAllStandardError());
    }

    // "[101]: 	315" lines -> reference -> value.
    static QMap<int, qint64> values(const QString &out)
    {
        QMap<int, qint64> v;
        static const QRegularExpression re(QStringLiteral("^\\[(\\d+)\\]:\\s+(-?\\d+)"),
                                           QRegularExpression::MultilineOption);
        auto it = re.globalMatch(out);
        while (it.hasNext()) {
            const auto m = it.next();
            v.insert(m.captured(1).toInt(), m.captured(2).toLongLong());
        }
        return v;
    }

private slots:
    void initTestCase()
    {
        m_mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
        DD_REQUIRE_TOOL(!m_mbpoll.isEmpty(), "mbpoll is not installed (apt install mbpoll)");
        DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this platform");
        m_pty = new PtyEndpoint;
        QVERIFY(!m_pty->open().isError());
        m_bus = new SimSerialBus(m_pty, this);
        SimServoModbusDrive::Config c;
        c.address = MbpollAddress;
        c.baud = MbpollBaud;
        c.firmware = 7051;
        m_drive = static_cast<SimServoModbusDrive *>(m_bus->addDevice(std::make_unique<SimServoModbusDrive>(c)));
    }

    void readsParameters()
    {
        int code = 0;
        const QString out = mbpoll({"-t", "4", "-r", "101", "-c", "10", m_pty->clientPath()}, &code);
        QVERIFY2(code == 0, qPrintable(out));
        const QMap<int, qint64> v = values(out);
        QCOMPARE(v.size(), 10);
        for (int n = 0; n < 10; ++n)
            QCOMPARE(v.value(101 + n), qint64(m_drive->parameter(n)));
        QCOMPARE(v.value(101), qint64(315));  // PA0
        QCOMPARE(v.value(103), qint64(7051)); // PA2: firmware
    }

    void readsTheMonitorBlock()
    {
        m_drive->setAlarm(7);
        int code = 0;
        const QString out = mbpoll({"-t", "4", "-r", "1", "-c", "20", m_pty->clientPath()}, &code);
        m_drive->setAlarm(0);
        QVERIFY2(code == 0, qPrintable(out));
        const QMap<int, qint64> v = values(out);
        QCOMPARE(v.size(), 20);
        QCOMPARE(v.value(20), qint64(7)); // DP-Err, register 0x13
    }

    void writesAreStoredByTheDrive()
    {
        // Two values: mbpoll writes them with function 0x10, which is what this drive takes.
        int code = 0;
        const QString out = mbpoll({"-t", "4", "-r", "111", m_pty->clientPath(), "1234", "4321"}, &code);
        QVERIFY2(code == 0, qPrintable(out));
        QCOMPARE(m_drive->parameter(10), quint16(1234));
        QCOMPARE(m_drive->parameter(11), quint16(4321));
        const QString back = mbpoll({"-t", "4", "-r", "111", "-c", "2", m_pty->clientPath()}, &code);
        QCOMPARE(values(back).value(111), qint64(1234));
        QCOMPARE(values(back).value(112), qint64(4321));
    }

    void readsBeyondTwentyRegistersAreRejected()
    {
        // The drive answers an exception (address byte 0x01 per the seed, not 5): libmodbus
        // refuses it ("Response not from requested slave"), and no data is printed.
        const quint64 before = m_drive->exceptionsSent();
        int code = 0;
        const QString out = mbpoll({"-t", "4", "-r", "101", "-c", "21", "-o", "0.3", m_pty->clientPath()}, &code);
        QCOMPARE(m_drive->exceptionsSent(), before + 1);
        QVERIFY2(values(out).isEmpty(), qPrintable(out));
        QVERIFY2(out.contains(QLatin1String("not from requested slave")), qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestMbpoll)
#include "tst_mbpoll.moc"

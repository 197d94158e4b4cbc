#include <QtTest>

#include <QFileInfo>
#include <QSerialPort>
#include <QTemporaryDir>

#include "sim/bus/ptyendpoint.h"
#include "tests/support/requiretool.h"

using namespace dd;

class TestPtyEndpoint : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase() { DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this system"); }

    void bytesFlowBothWays()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString link = dir.filePath(QStringLiteral("dd-sim"));
        PtyEndpoint pty;
        const Error err = pty.open(link);
        QVERIFY2(!err, qPrintable(err.message));
        QVERIFY(pty.isOpen());
        QVERIFY(pty.slavePath().startsWith(QLatin1String("/dev/")));
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(QFileInfo(link).symLinkTarget(), pty.slavePath());
        QCOMPARE(pty.clientPath(), link);
        QVERIFY(pty.description().contains(pty.slavePath()));

        QSerialPort client;
        client.setPortName(link);
        client.setBaudRate(19200);
        QVERIFY2(client.open(QIODevice::ReadWrite), qPrintable(client.errorString()));
        QCOMPARE(pty.hostBaud(), 19200);

        QSignalSpy received(&pty, &PtyEndpoint::received);
        const QByteArray request = QByteArray::fromHex("0103000000 0ac5cd00ff0d0a11");
        QCOMPARE(client.write(request), request.size());
        QByteArray got;
        QTRY_VERIFY_WITH_TIMEOUT((got =
                                      [&] {
                                          QByteArray all;
                                          for (const auto &args : std::as_const(received))
                                              all += args.at(0).toByteArray();
                                          return all;
                                      }())
                                     == request,
                                 2000);

        const QByteArray reply = QByteArray::fromHex("01030200 01 79 84 0a 0d 00 ff");
        QCOMPARE(pty.write(reply), reply.size());
        QTRY_COMPARE_WITH_TIMEOUT(client.bytesAvailable(), reply.size(), 2000);
        QCOMPARE(client.readAll(), reply); // raw: no CR/LF translation, no echo
        QCOMPARE(client.bytesAvailable(), 0);

        // hostBaud follows the client's settings
        QVERIFY(client.setBaudRate(115200));
        QCOMPARE(pty.hostBaud(), 115200);
        QVERIFY(client.setBaudRate(9600));
        QCOMPARE(pty.hostBaud(), 9600);
    }

    void clientMayCloseAndReopen()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        QCOMPARE(pty.linkPath(), QString());
        QCOMPARE(pty.clientPath(), pty.slavePath());
        QSignalSpy closed(&pty, &PtyEndpoint::closed);
        for (int round = 0; round < 3; ++round) {
            QSerialPort client;
            client.setPortName(pty.slavePath());
            client.setBaudRate(38400);
            QVERIFY2(client.open(QIODevice::ReadWrite), qPrintable(client.errorString()));
            QSignalSpy received(&pty, &PtyEndpoint::received);
            client.write("ping");
            QTRY_VERIFY_WITH_TIMEOUT(!received.isEmpty(), 2000);
            QCOMPARE(received.first().at(0).toByteArray(), QByteArray("ping"));
            pty.write("pong");
            QTRY_COMPARE_WITH_TIMEOUT(client.bytesAvailable(), 4, 2000);
            QCOMPARE(client.readAll(), QByteArray("pong"));
            client.close();
        }
        QVERIFY(pty.isOpen());
        QCOMPARE(closed.count(), 0);
    }

    void closingMakesTheAdapterVanish()
    {
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("dd-gone"));
        PtyEndpoint pty;
        QVERIFY(!pty.open(link));
        QSerialPort client;
        client.setPortName(pty.slavePath());
        client.setBaudRate(9600);
        QVERIFY(client.open(QIODevice::ReadWrite));
        QSignalSpy errors(&client, &QSerialPort::errorOccurred);
        QSignalSpy closed(&pty, &PtyEndpoint::closed);

        pty.close();
        QCOMPARE(closed.count(), 1);
        QVERIFY(!pty.isOpen());
        QVERIFY(!QFileInfo::exists(link));
        QVERIFY(!QFileInfo(link).isSymLink());
        QCOMPARE(pty.write("x"), -1);

        // The client's next read fails (a hung-up tty reads EOF): QSerialPort reports it.
        QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty() || !client.isOpen(), 3000);
        qInfo() << "client saw" << client.error() << client.errorString();
        pty.close(); // idempotent
        QCOMPARE(closed.count(), 1);
    }

    void linkNeverClobbersAFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("precious"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("keep me");
        f.close();
        PtyEndpoint pty;
        const Error err = pty.open(path);
        QCOMPARE(err.code, ErrorCode::OpenFailed);
        QVERIFY(err.message.contains(path));
        QVERIFY(!pty.isOpen());
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("keep me"));

        // A stale symlink (an earlier run that crashed) is replaced.
        const QString stale = dir.filePath(QStringLiteral("stale"));
        QVERIFY(QFile::link(QStringLiteral("/dev/null-nonexistent"), stale));
        QVERIFY(!pty.open(stale));
        QCOMPARE(QFileInfo(stale).symLinkTarget(), pty.slavePath());
    }
};

QTEST_GUILESS_MAIN(TestPtyEndpoint)
#include "tst_ptyendpoint.moc"

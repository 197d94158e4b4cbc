// ShuokeDrive's write-and-read-back against a scripted transport: what each write reports
// and the error a batch finishes with (WriteVerification), in cases the simulator does not
// produce: a drive that limits a value, a read-back that gets no answer, a lost answer.
#include <QtTest>

#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/drive/shuoke/shuokeparameter.h"
#include "core/drive/shuoke/shuoketransport.h"
#include "core/link/linkreply.h"

#include <QHash>

using namespace dd;
using namespace dd::shuoke;

namespace {

// A drive behind a transport without a wire: it keeps the settings written to it and
// answers GET with them, except where a test scripts otherwise.
class ScriptedTransport : public ShuokeTransport
{
public:
    enum class Act {
        Answer, // carried out and answered
        Lose,   // carried out, the answer is lost (timeout)
        Ignore, // not carried out, no answer (timeout)
    };

    explicit ScriptedTransport(QObject *parent = nullptr)
        : ShuokeTransport(scriptedOptions(), parent)
    {
    }

    bool open(const ConnectionSettings &, TrafficTap *, Error *) override { return true; }
    void close() override { }
    bool isOpen() const override { return true; }
    QString description() const override { return QStringLiteral("scripted"); }
    void cancelAll(const Error &) override { }

    QHash<quint8, qint64> values;     // by SET command
    QHash<quint8, qint64> limits;     // SET command -> the value the drive keeps instead
    QHash<quint8, QList<Act>> script; // by command (SET or GET); Answer when empty

protected:
    LinkReply *start(const ShuokeRequest &request, Error *) override
    {
        auto *reply = new LinkReply(this);
        const Frame &f = request.frame;
        const Act act = script[f.command].isEmpty() ? Act::Answer : script[f.command].takeFirst();
        const ShuokeParameter *set = ShuokeParameter::byIndex(f.command);
        const ShuokeParameter *get = nullptr;
        for (const ShuokeParameter &p : ShuokeParameter::all())
            if (p.isReadable() && p.readCommand == f.command)
                get = &p;
        Frame answer = Frame::make(f.address, f.command);
        if (set && act != Act::Ignore) {
            const qint64 v = *set->decode(f.data, ByteOrder::LittleEndian);
            values.insert(set->setCommand, limits.value(set->setCommand, v));
        } else if (get) {
            answer.data = get->encode(values.value(get->setCommand), ByteOrder::LittleEndian);
        }
        if (act == Act::Answer) {
            m_answers.insert(reply, answer);
            reply->finishWithFrame(QByteArray(1, '\0'));
        } else {
            reply->finishWithError({ErrorCode::Timeout, QStringLiteral("No reply within 100 ms.")});
        }
        return reply;
    }

    Decoded<Frame> decode(const LinkReply &reply, const ShuokeRequest &) const override
    {
        return Decoded<Frame>::success(m_answers.value(&reply));
    }

private:
    static ShuokeOptions scriptedOptions()
    {
        ShuokeOptions o;
        o.model = Model::M6505;
        return o;
    }

    QHash<const LinkReply *, Frame> m_answers;
};

bool finished(DriveReply *reply)
{
    return QTest::qWaitFor([reply] { return reply->isFinished(); }, 5000);
}

} // namespace

class TestShuokeWriteVerify : public QObject
{
    Q_OBJECT

private slots:
    void init()
    {
        m_transport = new ScriptedTransport(this);
        m_drive = new ShuokeDrive(m_transport, 1, this);
        m_transport->values = {{CmdSetMaxSpeed, 500}, {CmdSetAcceleration, 600}, {CmdSetDeceleration, 700}};
    }
    void cleanup()
    {
        delete m_drive;
        delete m_transport;
    }

    void verified()
    {
        DriveReply *r = m_drive->writeParameters({{CmdSetMaxSpeed, 1000}});
        QVERIFY(finished(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(r->writeResults().size(), 1);
        QCOMPARE(r->writeResults().first().outcome, WriteOutcome::Verified);
        QCOMPARE(r->writeResults().first().readBack, qint64(1000));
    }

    void mismatchesAreCountedAndTheFirstNamed()
    {
        m_transport->limits = {{CmdSetMaxSpeed, 900}, {CmdSetDeceleration, 800}};
        DriveReply *r = m_drive->writeParameters(
            {{CmdSetMaxSpeed, 1000}, {CmdSetAcceleration, 1000}, {CmdSetDeceleration, 1000}});
        QVERIFY(finished(r));
        QCOMPARE(r->error().code, ErrorCode::VerifyMismatch);
        QCOMPARE(r->error().message,
                 QStringLiteral("2 parameter(s) read back with another value than written (first: max-speed: "
                                "Wrote 1000, but the drive reads back 900.). The drive may limit the value or "
                                "not accept it in its present state, or the parameter may be read-only."));
        const QList<ParameterWriteResult> &w = r->writeResults();
        QCOMPARE(w.size(), 3);
        QCOMPARE(w.at(0).outcome, WriteOutcome::Mismatch);
        QVERIFY(w.at(0).written);
        QCOMPARE(w.at(0).readBack, qint64(900));
        QCOMPARE(w.at(1).outcome, WriteOutcome::Verified);
        QCOMPARE(w.at(2).outcome, WriteOutcome::Mismatch);
    }

    void aFailedReadBackOutweighsAnEarlierMismatch()
    {
        // Before WriteVerification the batch finished with VerifyMismatch here: the first
        // unverified write, whatever went wrong later.
        m_transport->limits = {{CmdSetMaxSpeed, 900}};
        m_transport->script[CmdGetAcceleration] = {ScriptedTransport::Act::Ignore, ScriptedTransport::Act::Ignore,
                                                   ScriptedTransport::Act::Ignore, ScriptedTransport::Act::Ignore};
        DriveReply *r = m_drive->writeParameters({{CmdSetMaxSpeed, 1000}, {CmdSetAcceleration, 1000}});
        QVERIFY(finished(r));
        QCOMPARE(r->error().code, ErrorCode::Timeout);
        QVERIFY2(
            r->error().message.startsWith(QStringLiteral("acceleration: Written, but it could not be read back: ")),
            qPrintable(r->error().message));
        const ParameterWriteResult &w = r->writeResults().at(1);
        QCOMPARE(w.outcome, WriteOutcome::ReadBackFailed);
        QVERIFY(w.written);
        QVERIFY(w.readBackFailed);
        QCOMPARE(m_transport->values.value(CmdSetAcceleration), qint64(1000));
    }

    void aLostAnswerIsJudgedByTheReadBack()
    {
        m_transport->script[CmdSetMaxSpeed] = {ScriptedTransport::Act::Lose};
        DriveReply *r = m_drive->writeParameters({{CmdSetMaxSpeed, 1000}});
        QVERIFY(finished(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(r->writeResults().first().outcome, WriteOutcome::Verified);
        QVERIFY(r->writeResults().first().written);
    }

    void anIgnoredWriteIsNotWritten()
    {
        m_transport->script[CmdSetMaxSpeed] = {ScriptedTransport::Act::Ignore};
        DriveReply *r = m_drive->writeParameters({{CmdSetMaxSpeed, 1000}});
        QVERIFY(finished(r));
        QCOMPARE(r->error().code, ErrorCode::Timeout);
        const ParameterWriteResult &w = r->writeResults().first();
        QCOMPARE(w.outcome, WriteOutcome::NotWritten);
        QVERIFY(!w.written);
        QVERIFY(!w.readBackFailed);
        QCOMPARE(w.readBack, qint64(500));
        QVERIFY2(w.error.endsWith(QStringLiteral("The drive did not take the value: it reads back 500.")),
                 qPrintable(w.error));
    }

    void noAnswerAtAllIsUnknown()
    {
        m_transport->script[CmdSetMaxSpeed] = {ScriptedTransport::Act::Lose};
        m_transport->script[CmdGetMaxSpeed] = {ScriptedTransport::Act::Ignore};
        DriveReply *r = m_drive->writeParameters({{CmdSetMaxSpeed, 1000}});
        QVERIFY(finished(r));
        QCOMPARE(r->error().code, ErrorCode::Timeout);
        const ParameterWriteResult &w = r->writeResults().first();
        QCOMPARE(w.outcome, WriteOutcome::Unknown);
        QVERIFY(!w.written);
        QVERIFY(w.readBackFailed);
        QVERIFY2(w.error.contains(QStringLiteral("whether the drive took the value is unknown")), qPrintable(w.error));
    }

private:
    ScriptedTransport *m_transport = nullptr;
    ShuokeDrive *m_drive = nullptr;
};

QTEST_GUILESS_MAIN(TestShuokeWriteVerify)
#include "tst_shuokewriteverify.moc"

#include "ui/panels/tuning/hubsteptest.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivereply.h"
#include "core/drive/driveresult.h"

#include <QPointer>
#include <QTimer>

namespace dd {

namespace {
const char *const ResultKey = "stepResult";
}

HubStepTest::HubStepTest(DriveHub *hub, int connectionId, int address, QObject *parent)
    : QObject(parent)
    , m_hub(hub)
    , m_connectionId(connectionId)
    , m_address(address)
{
}

void HubStepTest::start(const StepSpec &spec, const StepLimits &limits)
{
    if (m_running || !m_hub)
        return;
    m_running = true;
    m_phase = StepTest::Phase::Preparing;
    emit phaseChanged(m_phase);
    QPointer<HubStepTest> self(this);
    m_hub->run(
        m_connectionId, m_address,
        [spec, limits](Drive &d) {
            // On the I/O thread: the reply outlives the test (its child) until it finishes.
            auto *reply = new DriveReply(&d);
            auto *test = new StepTest(&d, reply);
            QObject::connect(test, &StepTest::progress, reply,
                             [reply](StepTest::Phase phase, const QString &) { reply->reportProgress(int(phase), 6); });
            QObject::connect(test, &StepTest::finished, reply, [reply](const StepResult &result) {
                reply->setInfo(QLatin1String(ResultKey), QVariant::fromValue(result));
                reply->finish(result.completed() ? Error::none() : result.error);
            });
            // Started from the event loop: the hub connects to the reply once this returns.
            QTimer::singleShot(0, reply, [test, reply, spec, limits] {
                if (Error e = test->start(spec, limits)) {
                    StepResult refused;
                    refused.outcome = StepResult::Outcome::Failed;
                    refused.abortCause = QStringLiteral("refused");
                    refused.error = e;
                    refused.reason = e.message;
                    refused.stopConfirmed = true;
                    reply->setInfo(QLatin1String(ResultKey), QVariant::fromValue(refused));
                    reply->finish(e);
                }
            });
            return reply;
        },
        [self](const DriveResult &r) {
            if (!self)
                return;
            self->m_running = false;
            self->m_phase = StepTest::Phase::Done;
            StepResult result;
            const QVariant v = r.info.value(QLatin1String(ResultKey));
            if (v.canConvert<StepResult>()) {
                result = v.value<StepResult>();
            } else { // the operation never ran (connection closed, no such drive)
                result.outcome = StepResult::Outcome::Failed;
                result.error = r.error;
                result.reason = r.error.message;
            }
            emit self->finished(result);
        },
        [self](int phase, int) {
            if (!self || !self->m_running)
                return;
            self->m_phase = StepTest::Phase(phase);
            emit self->phaseChanged(self->m_phase);
        });
}

void HubStepTest::stop()
{
    if (!m_running || !m_hub)
        return;
    m_hub->run(m_connectionId, m_address, [](Drive &d) { return d.stop(); });
}

} // namespace dd

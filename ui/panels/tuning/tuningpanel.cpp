#include "ui/panels/tuning/tuningpanel.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/driveresult.h"
#include "core/params/parameterdictionary.h"
#include "ui/common/displaytext.h"
#include "ui/common/livetext.h"
#include "ui/panels/tuning/capturecontrols.h"
#include "ui/panels/tuning/captureplot.h"
#include "ui/panels/tuning/hubcapture.h"
#include "ui/panels/tuning/hubsteptest.h"
#include "ui/panels/tuning/runcomparison.h"
#include "ui/panels/tuning/runlist.h"
#include "ui/panels/tuning/spectrumview.h"
#include "ui/panels/tuning/steptestcontrols.h"
#include "ui/panels/tuning/tuningparameterseditor.h"
#include "ui/workspace/driveparameters.h"

#include <QComboBox>
#include <QDateTime>
#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStyle>
#include <QTabWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace dd {

namespace {
// Overlay colours, by the run's place in the list (stable while runs are ticked on and off).
QColor runColor(int i)
{
    static const QList<QColor> colors{QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                                      QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                      QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf)};
    return colors.at(i % colors.size());
}
} // namespace

TuningPanel::TuningPanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
{
    m_capture = new HubCapture(context.hub, context.connectionId, context.address, this);
    m_step = new HubStepTest(context.hub, context.connectionId, context.address, this);
    buildUi();
    connect(m_step, &HubStepTest::phaseChanged, this, [this](StepTest::Phase phase) {
        showMessage(
            m_message,
            [phase] {
                switch (phase) {
                case StepTest::Phase::Preparing: return tr("Step test: reading the drive's state…");
                case StepTest::Phase::Arming: return tr("Step test: filling the capture before the motion…");
                case StepTest::Phase::Moving: return tr("Step test: moving…");
                case StepTest::Phase::Stopping: return tr("Step test: stopping…");
                case StepTest::Phase::Returning:
                    return tr("Step test: the axis moves back to its start position (STOP stops it)…");
                default: return tr("Step test: running…");
                }
            },
            MessageKind::Info);
    });
    connect(m_step, &HubStepTest::finished, this, &TuningPanel::onStepFinished);
    connect(m_capture, &HubCapture::stateChanged, this, &TuningPanel::updateCaptureState);
    connect(m_capture, &HubCapture::captured, this, &TuningPanel::onCaptured);
    connect(m_capture, &HubCapture::failed, this, [this](const Error &e) {
        const QString why = e.message;
        m_lastCaptureState = [why] { return why; };
        showMessage(
            m_message, [why] { return tr("Capture stopped: %1").arg(why); }, MessageKind::Problem);
        reportError(e);
        updateCaptureState();
    });
    retranslate();
    updateCaptureState();
}

TuningPanel::~TuningPanel() = default;

void TuningPanel::buildUi()
{
    m_unavailable = new QLabel(this);
    m_unavailable->setAlignment(Qt::AlignCenter);
    m_unavailable->setWordWrap(true);
    m_body = new QWidget(this);

    // Left: plot over results.
    m_plot = new CapturePlot(m_body);
    m_plotChannel = new QComboBox(m_body);
    m_plotChannel->setObjectName(QStringLiteral("plotChannel"));
    m_plotChannelLabel = new QLabel(m_body);
    auto *plotTop = new QHBoxLayout;
    plotTop->addWidget(m_plotChannelLabel);
    plotTop->addWidget(m_plotChannel, 1);
    auto *plotBox = new QWidget(m_body);
    auto *plotLayout = new QVBoxLayout(plotBox);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    plotLayout->addLayout(plotTop);
    plotLayout->addWidget(m_plot, 1);

    m_runs = new RunList(m_body);
    m_comparison = new RunComparison(m_body);
    auto *runsPage = new QWidget(m_body);
    auto *runsLayout = new QHBoxLayout(runsPage);
    runsLayout->setContentsMargins(4, 4, 4, 4);
    runsLayout->addWidget(m_runs, 1);
    runsLayout->addWidget(m_comparison, 2);
    m_spectrum = new SpectrumView(m_body);
    m_results = new QTabWidget(m_body);
    m_results->setObjectName(QStringLiteral("tuningResults"));
    m_results->addTab(runsPage, QString());
    m_results->addTab(m_spectrum, QString());

    auto *left = new QSplitter(Qt::Vertical, m_body);
    left->setChildrenCollapsible(false);
    left->addWidget(plotBox);
    left->addWidget(m_results);
    left->setStretchFactor(0, 3);
    left->setStretchFactor(1, 2);

    // Right: what to do, and the gains.
    m_stepControls = new StepTestControls(m_body);
    m_captureControls = new CaptureControls(m_body);
    m_actions = new QTabWidget(m_body);
    m_actions->setObjectName(QStringLiteral("tuningActions"));
    m_actions->addTab(m_stepControls, QString());
    m_actions->addTab(m_captureControls, QString());
    m_editor = new TuningParametersEditor(context(), m_body);
    m_editor->setMinimumHeight(150);
    m_apply = new QPushButton(m_body);
    m_apply->setObjectName(QStringLiteral("applyRunParameters"));
    m_parametersTitle = new QLabel(m_body);
    QFont bold = m_parametersTitle->font();
    bold.setBold(true);
    m_parametersTitle->setFont(bold);
    m_message = createMessageLabel(m_body, QStringLiteral("tuningPanelMessage"));

    auto *rightBox = new QWidget;
    auto *right = new QVBoxLayout(rightBox);
    right->setContentsMargins(0, 0, 4, 0);
    right->addWidget(m_actions);
    right->addWidget(m_parametersTitle);
    right->addWidget(m_editor, 1);
    right->addWidget(m_apply);
    right->addWidget(m_message);
    auto *scroll = new QScrollArea(m_body);
    scroll->setObjectName(QStringLiteral("tuningSide"));
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(rightBox);
    m_side = scroll;

    auto *body = new QHBoxLayout(m_body);
    body->setContentsMargins(0, 0, 0, 0);
    body->addWidget(left, 1);
    body->addWidget(scroll);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_unavailable);
    layout->addWidget(m_body, 1);

    connect(m_stepControls, &StepTestControls::runRequested, this, &TuningPanel::runStep);
    connect(m_stepControls, &StepTestControls::stopRequested, this, [this] { m_step->stop(); });
    connect(m_captureControls, &CaptureControls::armRequested, this, &TuningPanel::arm);
    connect(m_captureControls, &CaptureControls::forceRequested, this, &TuningPanel::force);
    connect(m_captureControls, &CaptureControls::stopRequested, this, &TuningPanel::stopCapture);
    connect(m_runs, &RunList::overlayChanged, this, &TuningPanel::updateOverlay);
    connect(m_runs, &RunList::selectionChanged, this, &TuningPanel::updateSelection);
    connect(m_runs, &RunList::fileUsed, this, &DrivePanel::fileUsed);
    connect(m_plotChannel, &QComboBox::currentIndexChanged, this, &TuningPanel::updateOverlay);
    connect(m_apply, &QPushButton::clicked, this, &TuningPanel::applySelectedRun);
    connect(m_editor, &TuningParametersEditor::errorOccurred, this, &TuningPanel::reportError);
    connect(m_editor, &TuningParametersEditor::busyChanged, this, &TuningPanel::updateSelection);
}

QString TuningPanel::title() const
{
    return tr("Tuning");
}

bool TuningPanel::openFile(const QString &path)
{
    if (!path.endsWith(QLatin1String(".ddrun"), Qt::CaseInsensitive))
        return false;
    m_runs->openFile(path);
    return true;
}

QStringList TuningPanel::captureChannels() const
{
    static const QStringList preferred{QStringLiteral("speed"), QStringLiteral("speed-command"),
                                       QStringLiteral("position-error"), QStringLiteral("torque"),
                                       QStringLiteral("current")};
    QStringList ids;
    for (const ChannelInfo &c : driveInfo().channels)
        if (preferred.contains(c.id))
            ids << c.id;
    for (int i = 0; ids.isEmpty() && i < qMin<qsizetype>(3, driveInfo().channels.size()); ++i)
        ids << driveInfo().channels.at(i).id;
    return ids;
}

void TuningPanel::arm()
{
    if (!context().isValid() || m_capture->isRunning())
        return;
    const CaptureSettings settings = m_captureControls->settings();
    QStringList channels = captureChannels();
    if (settings.trigger.isLevel() && !channels.contains(settings.trigger.channel))
        channels << settings.trigger.channel;
    if (channels.isEmpty()) {
        showMessage(
            m_message, [] { return tr("This drive reports no live channels to capture."); }, MessageKind::Problem);
        return;
    }
    m_message->clear();
    m_capture->start(settings, channels);
}

void TuningPanel::force()
{
    m_capture->forceTrigger();
}

void TuningPanel::stopCapture()
{
    m_capture->stop();
}

bool TuningPanel::isCapturing() const
{
    return m_capture->isRunning();
}

QString TuningPanel::message() const
{
    return m_message->text();
}

void TuningPanel::updateCaptureState()
{
    const bool running = m_capture->isRunning();
    QString state;
    if (running) {
        switch (m_capture->state()) {
        case CaptureRecorder::State::Filling: state = tr("Filling the pre-trigger window…"); break;
        case CaptureRecorder::State::Armed:
            state = tr("Armed: waiting for the trigger %1.").arg(m_capture->settings().trigger.toString());
            break;
        case CaptureRecorder::State::Recording: state = tr("Triggered: recording…"); break;
        default: state = tr("Capturing…"); break;
        }
    } else {
        state = m_lastCaptureState ? m_lastCaptureState() : QString();
    }
    m_captureControls->setRunning(running, state);
}

void TuningPanel::onCaptured(const CaptureData &capture)
{
    ++m_captureCount;
    const IntervalStats &s = capture.interval;
    const int samples = int(capture.time.size());
    const int pre = capture.preTriggerSamples;
    const double intervalMs = s.mean * 1000.0;
    m_lastCaptureState = [samples, pre, intervalMs] {
        return tr("Captured %1 samples (%2 before the trigger), interval %3 ms.")
            .arg(samples)
            .arg(pre)
            .arg(intervalMs, 0, 'f', 2);
    };
    updateCaptureState();

    TuningRun run;
    run.created = QDateTime::currentDateTimeUtc();
    run.family = familyId(context().family);
    run.address = context().address;
    run.model = driveInfo().identity.model;
    run.firmware = driveInfo().identity.firmware;
    const ConnectionSettings link = context().hub ? context().hub->connectionSettings(context().connectionId)
                                                  : ConnectionSettings{};
    run.linkKind = link.isCan() ? QStringLiteral("can") : QStringLiteral("serial");
    run.linkDescription = driveInfo().identity.link.isEmpty() ? link.linkName() : driveInfo().identity.link;
    run.settings = m_capture->settings();
    run.capture = capture;
    for (const QString &c : capture.channels) {
        QString unit;
        for (const ChannelInfo &i : driveInfo().channels)
            if (i.id == c)
                unit = i.unit;
        run.units << unit;
    }
    if (!capture.channels.isEmpty()) {
        StepMetrics::Input input;
        input.channel = capture.channels.contains(QStringLiteral("speed")) ? QStringLiteral("speed")
                                                                           : capture.channels.first();
        run.metricsChannel = input.channel;
        run.metrics = StepMetrics::compute(capture, input);
    }
    run.label = tr("capture %1 · %2")
                    .arg(m_captureCount)
                    .arg(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss")));

    addRunWithSnapshot(run);
}

void TuningPanel::addRunWithSnapshot(TuningRun run)
{
    if (!run.tuning.isEmpty()) {
        m_runs->addRun(run);
        return;
    }
    // The tuning parameters as the drive has them now (read, not assumed).
    QList<int> indices;
    for (const TuningEntry &e : m_editor->entries())
        indices << e.index;
    if (indices.isEmpty() || !context().isValid()) {
        addCapturedRun(run, {}, QString());
        return;
    }
    QPointer<TuningPanel> self(this);
    context().hub->run(
        context().connectionId, context().address, [indices](Drive &d) { return d.readParameters(indices); },
        [self, run](const DriveResult &r) {
            if (!self)
                return;
            if (self->parameters())
                self->parameters()->reportRead(r.parameters);
            self->addCapturedRun(run, r.parameters, r.ok() ? QString() : r.error.message);
        });
}

void TuningPanel::runStep()
{
    if (!context().isValid() || m_step->isRunning() || !m_stepControls->blockedReason().isEmpty())
        return;
    if (m_capture->isRunning()) {
        showMessage(
            m_message, [] { return tr("Not started: stop the free capture first."); }, MessageKind::Problem);
        return;
    }
    // Enabling is the engineer's act: a step would switch a disabled servo-can drive on.
    if (context().can(Capability::Enable) && !driveInfo().status.enabled) {
        showMessage(
            m_message,
            [] {
                return tr("Not started: the power stage is off. DriveDesk does not switch it on by itself: "
                          "enable it in the Motion tab first.");
            },
            MessageKind::Problem);
        return;
    }
    const StepTestControls::Request r = m_stepControls->request();
    StepSpec spec;
    spec.kind = r.test == StepTestControls::Test::Position ? StepSpec::Kind::Position
        : r.test == StepTestControls::Test::Reversal       ? StepSpec::Kind::Reversal
                                                           : StepSpec::Kind::Velocity;
    spec.speed = qint32(qRound(r.speed));
    spec.durationS = r.duration;
    spec.distance = qint64(qRound64(r.distance));
    spec.returnToStart = r.returnToStart;
    StepLimits limits;
    limits.maxSpeed = r.maxSpeed;
    limits.maxTravel = qint64(qRound64(r.maxTravel));
    limits.maxDurationS = r.maxDuration;
    if (Error e = limits.check(spec)) {
        const QString why = e.message;
        showMessage(
            m_message, [why] { return tr("Not started: %1").arg(why); }, MessageKind::Problem);
        return;
    }
    m_stepControls->setRunning(true);
    m_captureControls->setEnabled(false);
    m_step->start(spec, limits);
}

bool TuningPanel::isStepRunning() const
{
    return m_step->isRunning();
}

void TuningPanel::onStepFinished(const StepResult &result)
{
    m_stepControls->setRunning(false);
    m_captureControls->setEnabled(true);
    const QString reason = result.reason;
    const QString stopNote = result.stopNote;
    if (result.completed()) {
        const bool back = result.returnedToStart;
        showMessage(
            m_message,
            [back] {
                return back ? tr("Step test done; the axis is back at its start position.")
                            : tr("Step test done; the axis did not return to its start position.");
            },
            MessageKind::Success);
    } else {
        const bool stopped = result.stopConfirmed;
        const bool refused = !result.moved && result.abortCause == QLatin1String("refused");
        showMessage(
            m_message,
            [reason, stopNote, stopped, refused] {
                if (refused)
                    return tr("Step test not started: %1").arg(reason);
                QString text = tr("Step test ended early: %1").arg(reason);
                if (!stopNote.isEmpty())
                    text += QLatin1Char(' ') + stopNote;
                else if (!stopped)
                    text += QLatin1Char(' ') + tr("The axis was not seen at rest.");
                return text;
            },
            MessageKind::Problem);
        if (result.error.isError() && result.abortCause != QLatin1String("refused"))
            reportError(result.error);
    }
    if (!result.hasRun)
        return;
    TuningRun run = result.run;
    ++m_stepCount;
    const ConnectionSettings link = context().hub ? context().hub->connectionSettings(context().connectionId)
                                                  : ConnectionSettings{};
    run.linkKind = link.isCan() ? QStringLiteral("can") : QStringLiteral("serial");
    if (run.linkDescription.isEmpty())
        run.linkDescription = link.linkName();
    run.label = tr("%1 %2 · %3")
                    .arg(run.test)
                    .arg(m_stepCount)
                    .arg(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss")));
    if (run.outcome == QLatin1String("aborted"))
        run.label += QLatin1Char(' ') + tr("(aborted: %1)").arg(run.abortCause);
    addRunWithSnapshot(run);
}

void TuningPanel::addCapturedRun(TuningRun run, const QMap<int, qint64> &values, const QString &readError)
{
    for (const TuningEntry &e : m_editor->entries())
        if (values.contains(e.index))
            run.tuning.append({e.index, m_editor->keyOf(e.index), e.role, values.value(e.index)});
    if (!readError.isEmpty())
        run.notes = tr("The tuning parameters could not be read: %1").arg(readError);
    m_runs->addRun(run);
}

void TuningPanel::updatePlotChannels()
{
    QStringList ids;
    for (const TuningRun &r : m_runs->overlaidRuns())
        for (const QString &c : r.capture.channels)
            if (!ids.contains(c))
                ids << c;
    auto nameOf = [this](const QString &id) {
        for (const ChannelInfo &c : driveInfo().channels)
            if (c.id == id)
                return c.name; // translated by the drive code
        return id;
    };
    QStringList wanted, current;
    for (const QString &id : std::as_const(ids))
        wanted << id + QLatin1Char('\t') + nameOf(id);
    for (int i = 0; i < m_plotChannel->count(); ++i)
        current << m_plotChannel->itemData(i).toString() + QLatin1Char('\t') + m_plotChannel->itemText(i);
    if (current == wanted)
        return;
    const QString keep = m_plotChannel->currentData().toString();
    const QSignalBlocker block(m_plotChannel);
    m_plotChannel->clear();
    for (const QString &id : std::as_const(ids))
        m_plotChannel->addItem(nameOf(id), id);
    int i = m_plotChannel->findData(keep.isEmpty() ? QStringLiteral("speed") : keep);
    if (i < 0)
        i = m_plotChannel->findData(QStringLiteral("speed"));
    m_plotChannel->setCurrentIndex(i >= 0 ? i : 0);
}

void TuningPanel::updateOverlay()
{
    updatePlotChannels();
    const QString channel = m_plotChannel->currentData().toString();
    QList<CapturePlot::Curve> curves;
    QString unit;
    for (int i = 0; i < m_runs->count(); ++i) {
        if (!m_runs->isOverlaid(i))
            continue;
        const TuningRun &r = m_runs->run(i);
        const int c = r.capture.columnOf(channel);
        if (c < 0)
            continue;
        if (unit.isEmpty() && c < r.units.size())
            unit = r.units.at(c);
        curves.append({r.label, runColor(i), r.capture.time, r.capture.columns.at(c)});
    }
    const QString name = m_plotChannel->currentText();
    m_plot->setCurves(curves, unit.isEmpty() ? name : tr("%1 (%2)").arg(name, DisplayText::unit(unit)));
    m_comparison->setRuns(m_runs->overlaidRuns());
    updateSelection();
}

void TuningPanel::updateSelection()
{
    const TuningRun *run = m_runs->selectedRun();
    m_spectrum->setRun(run);
    QString reason;
    if (!run)
        reason = tr("Select a run whose parameters to apply.");
    else if (run->tuning.isEmpty())
        reason = tr("The selected run holds no tuning parameters.");
    else if (m_editor->isBusy())
        reason = tr("Busy with the drive.");
    m_apply->setEnabled(reason.isEmpty() && context().isValid());
    m_apply->setToolTip(reason);
}

void TuningPanel::applySelectedRun()
{
    const TuningRun *run = m_runs->selectedRun();
    if (!run || run->tuning.isEmpty())
        return;
    m_editor->applyRun(*run, driveInfo().identity);
}

void TuningPanel::loadDictionary()
{
    if (m_dictionaryAsked || !context().isValid())
        return;
    m_dictionaryAsked = true;
    auto dictionary = std::make_shared<std::shared_ptr<const ParameterDictionary>>();
    const Family family = context().family;
    auto indices = std::make_shared<QList<int>>();
    QPointer<TuningPanel> self(this);
    context().hub->run(
        context().connectionId, context().address,
        [dictionary, indices, family](Drive &d) {
            // A user's dictionary when one is set, else the family's bundled one.
            *dictionary = d.dictionary();
            if (!*dictionary)
                *dictionary = std::shared_ptr<const ParameterDictionary>(&ParameterDictionary::bundled(family),
                                                                         [](const ParameterDictionary *) {});
            for (const TuningEntry &e : TuningParametersEditor::entriesFor(**dictionary, family))
                *indices << e.index;
            return d.readParameters(*indices);
        },
        [self, dictionary, indices](const DriveResult &r) {
            if (!self)
                return;
            self->m_editor->setDictionary(*dictionary);
            if (self->parameters() && !r.parameters.isEmpty())
                self->parameters()->reportRead(r.parameters);
            if (!r.ok() && !indices->isEmpty())
                self->reportResult(r);
        });
}

void TuningPanel::activeChanged(bool active)
{
    if (active && driveInfo().valid)
        loadDictionary();
}

void TuningPanel::driveInfoChanged(const DriveInfo &info)
{
    m_captureControls->setChannels(info.channels);
    retranslate();
    if (isActive())
        loadDictionary();
}

void TuningPanel::alarmChanged(int code)
{
    if (code != 0)
        m_capture->alarmRaised();
}

void TuningPanel::retranslate()
{
    const DriveInfo &info = driveInfo();
    const bool monitor = info.capabilities.testFlag(Capability::Monitor);
    if (!info.valid)
        m_unavailable->setText(tr("Reading the drive's identity…"));
    else if (!monitor)
        m_unavailable->setText(
            tr("This drive offers no live values to capture: %1").arg(info.reason(Capability::Monitor)));
    m_unavailable->setVisible(!info.valid || !monitor);
    m_body->setVisible(info.valid && monitor);

    m_plotChannelLabel->setText(tr("Show:"));
    m_results->setTabText(0, tr("Runs"));
    m_results->setTabText(1, tr("Spectrum"));
    m_actions->setTabText(0, tr("Step test"));
    m_actions->setTabText(1, tr("Capture"));
    m_parametersTitle->setText(tr("Tuning parameters"));
    m_apply->setText(tr("Apply this run's parameters"));
    const bool canMove = info.capabilities.testFlag(Capability::Jog)
        || info.capabilities.testFlag(Capability::MoveRelative);
    m_stepControls->setAvailable(info.valid && monitor && canMove,
                                 !canMove
                                     ? tr("This drive cannot be moved from here: %1").arg(info.reason(Capability::Jog))
                                     : tr("The drive's live values are needed for a step test."));
    for (const ChannelInfo &c : info.channels)
        if (c.id == QLatin1String("speed"))
            m_stepControls->setSpeedUnit(c.unit);
    updateCaptureState();
    QMap<QString, QString> names;
    for (const ChannelInfo &c : info.channels)
        names.insert(c.id, c.name);
    m_spectrum->setChannelNames(names);
    updateOverlay(); // channel names follow the language
    updateSideWidth();
}

void TuningPanel::updateSideWidth()
{
    // As wide as its content needs beside a vertical scroll bar: never cut, never scrolled
    // sideways (the content's needs change with the language).
    QWidget *content = m_side->widget();
    content->adjustSize();
    const int bar = m_side->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, m_side);
    const int need = std::max(240, content->minimumSizeHint().width()) + bar + 2 * m_side->frameWidth();
    m_side->setFixedWidth(std::min(need, 380));
}

void TuningPanel::showEvent(QShowEvent *event)
{
    DrivePanel::showEvent(event);
    updateSideWidth();
}

} // namespace dd

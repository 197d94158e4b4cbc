#include "ui/panels/motion/motionreadout.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/driveresult.h"
#include "ui/common/displaytext.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QTimer>
#include <QVBoxLayout>

namespace dd {

namespace {
// The big values, in the order shown.
const char *const kValueIds[] = {"speed", "position", "position-error"};
const QLatin1String kStatusId("status");
constexpr MotionReadout::Switch kSwitches[] = {MotionReadout::Switch::LeftLimit, MotionReadout::Switch::Origin,
                                               MotionReadout::Switch::RightLimit};

int bitOf(MotionReadout::Switch s)
{
    switch (s) {
    case MotionReadout::Switch::LeftLimit: return StatusChannelBits::LeftLimit;
    case MotionReadout::Switch::Origin: return StatusChannelBits::Origin;
    case MotionReadout::Switch::RightLimit: return StatusChannelBits::RightLimit;
    }
    return 0;
}
} // namespace

MotionReadout::MotionReadout(const DriveContext &context, QWidget *parent)
    : QWidget(parent)
    , m_context(context)
{
    setObjectName(QStringLiteral("motionReadout"));
    auto *values = new QHBoxLayout;
    values->setContentsMargins(0, 0, 0, 0);
    for (const char *id : kValueIds) {
        Value v;
        v.box = new QWidget(this);
        v.box->setObjectName(QStringLiteral("readout-%1").arg(QLatin1String(id)));
        v.title = new QLabel(v.box);
        v.title->setForegroundRole(QPalette::PlaceholderText);
        v.title->setWordWrap(true);
        v.value = new QLabel(QStringLiteral("—"), v.box);
        v.value->setObjectName(QStringLiteral("readoutValue-%1").arg(QLatin1String(id)));
        v.value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        QFont big = v.value->font();
        big.setPointSizeF(big.pointSizeF() * 2.0);
        big.setBold(true);
        v.value->setFont(big);
        auto *box = new QVBoxLayout(v.box);
        box->setContentsMargins(0, 0, 12, 0);
        box->setSpacing(0);
        box->addWidget(v.title);
        box->addWidget(v.value);
        v.box->hide();
        values->addWidget(v.box, 1);
        m_values.insert(QLatin1String(id), v);
    }
    m_switchBox = new QWidget(this);
    m_switchBox->setObjectName(QStringLiteral("switchIndicators"));
    auto *switches = new QHBoxLayout(m_switchBox);
    switches->setContentsMargins(0, 0, 0, 0);
    for (Switch s : kSwitches) {
        auto *l = new QLabel(m_switchBox);
        l->setObjectName(QStringLiteral("switch%1").arg(int(s)));
        switches->addWidget(l);
        m_switchLabels.insert(s, l);
    }
    switches->addStretch(1);
    m_switchBox->hide();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(values);
    layout->addWidget(m_switchBox);

    m_timer = new QTimer(this);
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, &MotionReadout::readNow);
    retranslate();
}

void MotionReadout::setChannels(const QList<ChannelInfo> &channels)
{
    m_ids.clear();
    m_hasStatus = false;
    for (auto it = m_values.begin(); it != m_values.end(); ++it)
        it->channel = ChannelInfo();
    for (const ChannelInfo &c : channels) {
        if (auto it = m_values.find(c.id); it != m_values.end()) {
            it->channel = c;
            m_ids << c.id;
        } else if (c.id == kStatusId) {
            m_hasStatus = true;
            m_ids << c.id;
        }
    }
    for (auto it = m_values.begin(); it != m_values.end(); ++it)
        it->box->setVisible(!it->channel.id.isEmpty());
    m_switchBox->setVisible(m_hasStatus);
    setVisible(!m_ids.isEmpty());
    retranslate();
    if (m_polling && !m_reading)
        readNow();
}

void MotionReadout::setPolling(bool on)
{
    if (m_polling == on)
        return;
    m_polling = on;
    if (!on) {
        m_timer->stop();
        return;
    }
    if (!m_reading)
        readNow();
}

void MotionReadout::readNow()
{
    if (!m_polling || m_ids.isEmpty() || !m_context.isValid())
        return;
    m_reading = true;
    const int generation = ++m_generation;
    QPointer<MotionReadout> self(this);
    m_context.hub->run(
        m_context.connectionId, m_context.address, [ids = m_ids](Drive &d) { return d.readChannels(ids); },
        [self, generation](const DriveResult &r) {
            if (!self || generation != self->m_generation)
                return;
            self->m_reading = false;
            self->onSamples(r.ok(), r.samples);
            if (self->m_polling)
                self->m_timer->start(ReadGapMs);
        });
}

void MotionReadout::onSamples(bool ok, const QMap<QString, double> &samples)
{
    ++m_reads;
    for (auto it = m_values.begin(); it != m_values.end(); ++it) {
        if (it->channel.id.isEmpty())
            continue;
        const auto s = samples.constFind(it->channel.id);
        it->last = ok && s != samples.cend() ? std::optional<double>(*s) : std::nullopt;
        showValue(*it);
    }
    const auto status = samples.constFind(kStatusId);
    if (ok && status != samples.cend())
        m_statusBits = int(*status);
    else
        m_statusBits.reset();
    showSwitches();
    emit updated();
}

QString MotionReadout::valueText(const QString &channelId) const
{
    const auto it = m_values.constFind(channelId);
    return it == m_values.cend() || it->channel.id.isEmpty() ? QString() : it->value->text();
}

std::optional<bool> MotionReadout::switchActive(Switch s) const
{
    if (!m_hasStatus || !m_statusBits)
        return std::nullopt;
    return (*m_statusBits & bitOf(s)) != 0;
}

bool MotionReadout::showsSwitches() const
{
    return m_hasStatus;
}

QString MotionReadout::switchName(Switch s) const
{
    switch (s) {
    case Switch::LeftLimit: return tr("Left limit");
    case Switch::Origin: return tr("Origin");
    case Switch::RightLimit: return tr("Right limit");
    }
    return {};
}

void MotionReadout::showSwitches()
{
    for (Switch s : kSwitches) {
        QLabel *l = m_switchLabels.value(s);
        const std::optional<bool> on = switchActive(s);
        // A dot and the switch's name; the state in words in the tool tip.
        const QString colour = !on ? QStringLiteral("#9e9e9e")
                                   : (*on ? QStringLiteral("#c62828") : QStringLiteral("#2e7d32"));
        if (s == Switch::Origin && on && *on)
            l->setText(QStringLiteral("<span style=\"color:#1565c0\">●</span> %1").arg(switchName(s).toHtmlEscaped()));
        else
            l->setText(
                QStringLiteral("<span style=\"color:%1\">●</span> %2").arg(colour, switchName(s).toHtmlEscaped()));
        l->setToolTip(!on ? tr("%1: not read yet").arg(switchName(s))
                          : (*on ? tr("%1: active").arg(switchName(s)) : tr("%1: not active").arg(switchName(s))));
    }
}

void MotionReadout::showValue(const Value &v)
{
    if (!v.last) {
        v.value->setText(QStringLiteral("—"));
        return;
    }
    QString text = QLocale().toString(*v.last, 'f', v.channel.decimals);
    if (!v.channel.unit.isEmpty())
        text += QLatin1Char(' ') + DisplayText::unit(v.channel.unit);
    v.value->setText(text);
}

void MotionReadout::retranslate()
{
    for (auto it = m_values.begin(); it != m_values.end(); ++it) {
        const QString &id = it.key();
        QString title = id == QLatin1String("speed") ? tr("Speed")
            : id == QLatin1String("position")        ? tr("Position")
                                                     : tr("Following error");
        it->title->setText(title);
        it->box->setToolTip(it->channel.name);
        if (!it->channel.id.isEmpty())
            showValue(*it); // the unit in the new language, also on a tab not read now
    }
    showSwitches();
}

} // namespace dd

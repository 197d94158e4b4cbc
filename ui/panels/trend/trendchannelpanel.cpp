#include "ui/panels/trend/trendchannelpanel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace dd {

namespace {

QIcon swatch(const QColor &color)
{
    QPixmap pm(12, 12);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.fillRect(QRect(1, 1, 10, 10), color);
    p.setPen(color.darker(150));
    p.drawRect(QRect(1, 1, 9, 9));
    return QIcon(pm);
}

} // namespace

TrendChannelPanel::TrendChannelPanel(QWidget *parent)
    : QWidget(parent)
    , m_grid(new QGridLayout)
    , m_scaleHeader(new QLabel(this))
    , m_offsetHeader(new QLabel(this))
{
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addLayout(m_grid);
    outer->addStretch(1);
    m_grid->addWidget(m_scaleHeader, 0, 1);
    m_grid->addWidget(m_offsetHeader, 0, 2);
    retranslateUi();
}

void TrendChannelPanel::retranslateUi()
{
    m_scaleHeader->setText(tr("Scale ×"));
    m_offsetHeader->setText(tr("Offset +"));
    const QString scaleTip = tr("The plot shows value × scale + offset; readouts and exports "
                                "show the real value.");
    m_scaleHeader->setToolTip(scaleTip);
    m_offsetHeader->setToolTip(scaleTip);
    for (const TrendChannel &c : std::as_const(m_channels)) {
        const Row row = m_rows.value(c.id);
        if (!row.check)
            continue;
        row.check->setToolTip(tr("Show %1 in the plot").arg(c.label()));
        row.scale->setToolTip(scaleTip);
        row.offset->setToolTip(scaleTip);
    }
}

void TrendChannelPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void TrendChannelPanel::setChannels(const QList<TrendChannel> &channels, const QList<QColor> &colors)
{
    for (const Row &row : std::as_const(m_rows)) {
        delete row.check;
        delete row.scale;
        delete row.offset;
    }
    m_rows.clear();
    m_channels = channels;
    int r = 1;
    for (const TrendChannel &c : channels) {
        const Settings s = m_settings.value(c.id);
        m_settings.insert(c.id, s);
        Row row;
        row.check = new QCheckBox(c.label(), this);
        row.check->setChecked(s.visible);
        row.check->setIcon(swatch(colors.value(r - 1, Qt::black)));
        row.scale = new QDoubleSpinBox(this);
        row.scale->setDecimals(4);
        row.scale->setRange(0.0001, 10000.0);
        row.scale->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
        row.scale->setValue(s.scale);
        row.scale->setKeyboardTracking(false);
        row.offset = new QDoubleSpinBox(this);
        row.offset->setDecimals(2);
        row.offset->setRange(-1e7, 1e7);
        row.offset->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
        row.offset->setValue(s.offset);
        row.offset->setKeyboardTracking(false);
        m_grid->addWidget(row.check, r, 0);
        m_grid->addWidget(row.scale, r, 1);
        m_grid->addWidget(row.offset, r, 2);
        ++r;
        const QString id = c.id;
        connect(row.check, &QCheckBox::toggled, this, [this, id](bool on) {
            m_settings[id].visible = on;
            emit visibilityChanged(id, on);
        });
        const auto onScale = [this, id, row] {
            Settings &st = m_settings[id];
            st.scale = row.scale->value();
            st.offset = row.offset->value();
            emit scaleChanged(id, st.scale, st.offset);
        };
        connect(row.scale, &QDoubleSpinBox::valueChanged, this, onScale);
        connect(row.offset, &QDoubleSpinBox::valueChanged, this, onScale);
        m_rows.insert(id, row);
    }
    retranslateUi();
}

void TrendChannelPanel::setChannelVisible(const QString &id, bool visible)
{
    m_settings[id].visible = visible;
    if (QCheckBox *box = checkBox(id))
        box->setChecked(visible); // emits visibilityChanged when it changes
}

void TrendChannelPanel::setChannelScale(const QString &id, double scale, double offset)
{
    Settings &s = m_settings[id];
    s.scale = scale;
    s.offset = offset;
    const Row row = m_rows.value(id);
    if (row.scale) {
        const QSignalBlocker b1(row.scale);
        const QSignalBlocker b2(row.offset);
        row.scale->setValue(scale);
        row.offset->setValue(offset);
        s.scale = row.scale->value(); // as clamped by the spin box
        s.offset = row.offset->value();
    }
    emit scaleChanged(id, s.scale, s.offset);
}

QCheckBox *TrendChannelPanel::checkBox(const QString &id) const
{
    return m_rows.value(id).check;
}

} // namespace dd

#include "ui/panels/trend/trendchannelpanel.h"
#include "ui/common/displaytext.h"

#include <QActionGroup>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QMenu>
#include <QPainter>
#include <QPixmap>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

namespace dd {

namespace {

constexpr int IdRole = Qt::UserRole + 1;

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
    , m_list(new QListWidget(this))
    , m_menuButton(new QToolButton(this))
{
    m_list->setObjectName(QStringLiteral("trendChannelList"));
    m_list->setTextElideMode(Qt::ElideMiddle);
    m_list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_list->setUniformItemSizes(true);
    m_list->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_list, &QListWidget::itemChanged, this, [this](QListWidgetItem *item) {
        if (m_filling)
            return;
        const QString id = item->data(IdRole).toString();
        const bool on = item->checkState() == Qt::Checked;
        if (m_settings.value(id).visible == on)
            return;
        m_settings[id].visible = on;
        emit visibilityChanged(id, on);
    });
    connect(m_list, &QListWidget::customContextMenuRequested, this, [this](const QPoint &pos) {
        if (QListWidgetItem *item = m_list->itemAt(pos))
            menuFor(item->data(IdRole).toString())->popup(m_list->viewport()->mapToGlobal(pos));
    });
    m_menuButton->setObjectName(QStringLiteral("trendChannelMenuButton"));
    m_menuButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_menuButton->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    connect(m_menuButton, &QToolButton::clicked, this, [this] {
        QListWidgetItem *item = m_list->currentItem() ? m_list->currentItem() : m_list->item(0);
        if (item)
            menuFor(item->data(IdRole).toString())->popup(m_menuButton->mapToGlobal(QPoint(0, m_menuButton->height())));
    });
    connect(m_list, &QListWidget::currentItemChanged, this, [this] { m_menuButton->setEnabled(m_list->count() > 0); });

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_list, 1);
    layout->addWidget(m_menuButton);
    // Compact: the plot gets the width. Long names are elided (tooltip: the full label).
    setMinimumWidth(120);
    setMaximumWidth(220);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Expanding);
    retranslateUi();
}

void TrendChannelPanel::retranslateUi()
{
    m_menuButton->setText(tr("Axis, scale…"));
    m_menuButton->setToolTip(tr("The selected channel's axis, scale and offset (also: right click a channel)"));
    m_list->setToolTip(QString());
    for (const TrendChannel &c : std::as_const(m_channels))
        updateItem(c.id);
}

void TrendChannelPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void TrendChannelPanel::setChannels(const QList<TrendChannel> &channels)
{
    const QString leftUnit = channels.isEmpty() ? QString() : channels.first().unit;
    for (const TrendChannel &c : channels) {
        if (!m_settings.contains(c.id)) {
            Settings s;
            s.axis = c.unit == leftUnit ? 0 : 1;
            m_settings.insert(c.id, s);
        }
    }
    m_channels = channels;
    m_filling = true;
    const QString current = m_list->currentItem() ? m_list->currentItem()->data(IdRole).toString() : QString();
    m_list->clear();
    for (const TrendChannel &c : std::as_const(m_channels)) {
        auto *item = new QListWidgetItem(m_list);
        item->setData(IdRole, c.id);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
        if (c.id == current)
            m_list->setCurrentItem(item);
    }
    m_filling = false;
    for (const TrendChannel &c : std::as_const(m_channels))
        updateItem(c.id);
    m_menuButton->setEnabled(!m_channels.isEmpty());
}

void TrendChannelPanel::setColors(const QHash<QString, QColor> &colors)
{
    m_colors = colors;
    for (const TrendChannel &c : std::as_const(m_channels))
        updateItem(c.id);
}

QListWidgetItem *TrendChannelPanel::item(const QString &id) const
{
    for (int i = 0; i < m_list->count(); ++i)
        if (m_list->item(i)->data(IdRole).toString() == id)
            return m_list->item(i);
    return nullptr;
}

void TrendChannelPanel::updateItem(const QString &id)
{
    QListWidgetItem *it = item(id);
    if (!it)
        return;
    TrendChannel channel;
    for (const TrendChannel &c : std::as_const(m_channels))
        if (c.id == id)
            channel = c;
    const Settings s = m_settings.value(id);
    const bool filling = m_filling;
    m_filling = true;
    QString text = DisplayText::channelLabel(channel.name.isEmpty() ? channel.id : channel.name, channel.unit);
    const QLocale locale;
    if (s.scale != 1.0 || s.offset != 0.0)
        text += QStringLiteral(" ×") + locale.toString(s.scale, 'g', 6);
    it->setText(text);
    it->setToolTip(tr("%1 — on the %2 axis. Right click: axis, scale and offset.")
                       .arg(text, s.axis == 0 ? tr("left") : tr("right")));
    it->setIcon(swatch(m_colors.value(id, Qt::gray)));
    it->setCheckState(s.visible ? Qt::Checked : Qt::Unchecked);
    m_filling = filling;
}

void TrendChannelPanel::setChannelVisible(const QString &id, bool visible)
{
    if (!m_settings.contains(id))
        m_settings.insert(id, Settings{});
    if (m_settings[id].visible == visible)
        return;
    m_settings[id].visible = visible;
    updateItem(id);
    emit visibilityChanged(id, visible);
}

void TrendChannelPanel::setChannelScale(const QString &id, double scale, double offset)
{
    if (!std::isfinite(scale) || scale == 0.0 || !std::isfinite(offset))
        return; // a zero scale would flatten the channel; the menu never offers it
    Settings &s = m_settings[id];
    if (s.scale == scale && s.offset == offset)
        return;
    s.scale = scale;
    s.offset = offset;
    updateItem(id);
    emit scaleChanged(id, scale, offset);
}

void TrendChannelPanel::setChannelAxis(const QString &id, int axis)
{
    axis = axis == 0 ? 0 : 1;
    Settings &s = m_settings[id];
    if (s.axis == axis)
        return;
    s.axis = axis;
    updateItem(id);
    emit axisChanged(id, axis);
}

QMenu *TrendChannelPanel::menuFor(const QString &id)
{
    delete m_menu;
    m_menu = new QMenu(this);
    m_menu->setObjectName(QStringLiteral("trendChannelMenu"));
    const Settings s = m_settings.value(id);
    auto *group = new QActionGroup(m_menu);
    QAction *left = m_menu->addAction(tr("Left axis"));
    QAction *right = m_menu->addAction(tr("Right axis"));
    for (QAction *a : {left, right}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    left->setObjectName(QStringLiteral("leftAxis"));
    right->setObjectName(QStringLiteral("rightAxis"));
    (s.axis == 0 ? left : right)->setChecked(true);
    connect(left, &QAction::triggered, this, [this, id] { setChannelAxis(id, 0); });
    connect(right, &QAction::triggered, this, [this, id] { setChannelAxis(id, 1); });
    m_menu->addSeparator();
    QAction *scale = m_menu->addAction(tr("Scale and offset…"));
    scale->setObjectName(QStringLiteral("scale"));
    connect(scale, &QAction::triggered, this, [this, id] { editScale(id); });
    QAction *reset = m_menu->addAction(tr("Reset scale and offset"));
    reset->setObjectName(QStringLiteral("resetScale"));
    reset->setEnabled(s.scale != 1.0 || s.offset != 0.0);
    connect(reset, &QAction::triggered, this, [this, id] { setChannelScale(id, 1.0, 0.0); });
    return m_menu;
}

void TrendChannelPanel::editScale(const QString &id)
{
    const Settings s = m_settings.value(id);
    QDialog dialog(this);
    TrendChannel channel;
    for (const TrendChannel &c : std::as_const(m_channels))
        if (c.id == id)
            channel = c;
    dialog.setWindowTitle(
        tr("Scale and offset: %1")
            .arg(DisplayText::channelLabel(channel.name.isEmpty() ? channel.id : channel.name, channel.unit)));
    auto *scale = new QDoubleSpinBox(&dialog);
    scale->setRange(-1e6, 1e6);
    scale->setDecimals(6);
    scale->setValue(s.scale);
    auto *offset = new QDoubleSpinBox(&dialog);
    offset->setRange(-1e9, 1e9);
    offset->setDecimals(3);
    offset->setValue(s.offset);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    auto *form = new QFormLayout(&dialog);
    auto *note = new QLabel(tr("The plot draws value × scale + offset; readouts and exports show the real value."),
                            &dialog);
    note->setWordWrap(true);
    form->addRow(note);
    form->addRow(tr("Scale ×"), scale);
    form->addRow(tr("Offset +"), offset);
    form->addRow(buttons);
    if (dialog.exec() == QDialog::Accepted && scale->value() != 0.0)
        setChannelScale(id, scale->value(), offset->value());
}

} // namespace dd

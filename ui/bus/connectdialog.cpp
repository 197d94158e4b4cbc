#include "ui/bus/connectdialog.h"

#include "core/link/cansettings.h"
#include "core/protocol/familytraits.h"
#include "ui/bus/serialportwatcher.h"

#include <QCanBus>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace dd {

namespace {
const QString DetectId = QStringLiteral("detect");

void selectData(QComboBox *box, const QVariant &value)
{
    const int i = box->findData(value);
    if (i >= 0)
        box->setCurrentIndex(i);
}

// A label and the field it names (its buddy), made in that order.
template <typename Field>
Field *labelledField(QWidget *parent, const QString &objectName, QLabel **label)
{
    *label = new QLabel(parent);
    auto *field = new Field(parent);
    field->setObjectName(objectName);
    (*label)->setBuddy(field);
    return field;
}
} // namespace

ConnectDialog::ConnectDialog(QWidget *parent)
    : QDialog(parent)
    , m_watcher(new SerialPortWatcher(this))
{
    setObjectName(QStringLiteral("connectDialog"));
    buildLinkBox();
    buildDriveBox();
    buildScanBox();
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ConnectDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_linkBox);
    layout->addWidget(m_driveBox);
    layout->addWidget(m_scanBox);
    layout->addStretch(1);
    layout->addWidget(m_buttons);

    connect(m_serialRadio, &QRadioButton::toggled, this, [this] {
        m_linkPages->setCurrentIndex(isCan() ? 1 : 0);
        fillFramings();
        updateEnabled();
    });
    connect(m_family, &QComboBox::currentIndexChanged, this, [this] {
        fillFramings();
        updateEnabled();
    });
    connect(m_watcher, &SerialPortWatcher::portsChanged, this, &ConnectDialog::fillPorts);

    retranslate();
    fillCanPlugins();
    fillFramings();
    updateEnabled();
}

void ConnectDialog::buildLinkBox()
{
    m_linkBox = new QGroupBox(this);
    m_serialRadio = new QRadioButton(m_linkBox);
    m_canRadio = new QRadioButton(m_linkBox);
    m_serialRadio->setChecked(true);
    m_linkPages = new QStackedWidget(m_linkBox);
    m_linkPages->addWidget(createSerialPage());
    m_linkPages->addWidget(createCanPage());
    auto *radios = new QHBoxLayout;
    radios->addWidget(m_serialRadio);
    radios->addWidget(m_canRadio);
    radios->addStretch(1);
    auto *linkLayout = new QVBoxLayout(m_linkBox);
    linkLayout->addLayout(radios);
    linkLayout->addWidget(m_linkPages);
}

QWidget *ConnectDialog::createSerialPage()
{
    auto *page = new QWidget;
    auto *form = new QFormLayout(page);
    form->setContentsMargins(0, 0, 0, 0);
    m_port = labelledField<QComboBox>(page, QStringLiteral("portCombo"), &m_portLabel);
    m_port->setEditable(true);
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumContentsLength(36);
    m_port->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_baud = labelledField<QComboBox>(page, QStringLiteral("baudCombo"), &m_baudLabel);
    m_baud->addItem(QString(), 0);
    for (int b : {4800, 9600, 19200, 38400, 57600, 115200, 230400})
        m_baud->addItem(QString::number(b), b);
    m_sweep = new QCheckBox(page);
    form->addRow(m_portLabel, m_port);
    form->addRow(m_baudLabel, m_baud);
    form->addRow(QString(), m_sweep);
    m_noPorts = new QWidget(page);
    m_noPorts->setObjectName(QStringLiteral("noPortsHint"));
    auto *hint = new QHBoxLayout(m_noPorts);
    hint->setContentsMargins(0, 0, 0, 0);
    m_noPortsText = new QLabel(m_noPorts);
    m_noPortsText->setWordWrap(true);
    m_demo = new QPushButton(m_noPorts);
    m_demo->setObjectName(QStringLiteral("startDemoButton"));
    connect(m_demo, &QPushButton::clicked, this, [this] { done(DemoRequested); });
    hint->addWidget(m_noPortsText, 1);
    hint->addWidget(m_demo, 0, Qt::AlignTop);
    m_noPorts->hide();
    form->addRow(m_noPorts);
    return page;
}

QWidget *ConnectDialog::createCanPage()
{
    auto *page = new QWidget;
    auto *form = new QFormLayout(page);
    form->setContentsMargins(0, 0, 0, 0);
    m_plugin = labelledField<QComboBox>(page, QStringLiteral("canPluginCombo"), &m_pluginLabel);
    m_interface = labelledField<QComboBox>(page, QStringLiteral("canInterfaceCombo"), &m_interfaceLabel);
    m_interface->setEditable(true);
    m_interface->setInsertPolicy(QComboBox::NoInsert);
    m_refreshCan = new QPushButton(page);
    auto *ifaceRow = new QHBoxLayout;
    ifaceRow->addWidget(m_interface, 1);
    ifaceRow->addWidget(m_refreshCan);
    m_bitrate = labelledField<QComboBox>(page, QStringLiteral("bitrateCombo"), &m_bitrateLabel);
    m_bitrate->addItem(QString(), 0);
    for (int b : {1000000, 500000, 250000, 125000, 100000, 50000, 20000})
        m_bitrate->addItem(tr("%1 kbit/s").arg(b / 1000), b);
    m_canError = new QLabel(page);
    m_canError->setWordWrap(true);
    m_canError->setStyleSheet(QStringLiteral("color: #c62828;"));
    form->addRow(m_pluginLabel, m_plugin);
    form->addRow(m_interfaceLabel, ifaceRow);
    form->addRow(m_bitrateLabel, m_bitrate);
    form->addRow(QString(), m_canError);
    connect(m_plugin, &QComboBox::currentIndexChanged, this, &ConnectDialog::fillCanInterfaces);
    connect(m_refreshCan, &QPushButton::clicked, this, &ConnectDialog::fillCanInterfaces);
    return page;
}

void ConnectDialog::buildDriveBox()
{
    m_driveBox = new QGroupBox(this);
    auto *driveForm = new QFormLayout(m_driveBox);
    m_family = labelledField<QComboBox>(m_driveBox, QStringLiteral("familyCombo"), &m_familyLabel);
    m_framing = labelledField<QComboBox>(m_driveBox, QStringLiteral("framingCombo"), &m_framingLabel);
    driveForm->addRow(m_familyLabel, m_family);
    driveForm->addRow(m_framingLabel, m_framing);
}

void ConnectDialog::buildScanBox()
{
    m_scanBox = new QGroupBox(this);
    m_scanBox->setCheckable(true);
    m_scanBox->setChecked(true);
    auto *scanForm = new QFormLayout(m_scanBox);
    m_rangeLabel = new QLabel(m_scanBox);
    m_from = new QSpinBox(m_scanBox);
    m_to = new QSpinBox(m_scanBox);
    m_from->setRange(0, 255);
    m_to->setRange(0, 255);
    m_from->setValue(ConnectRequest::DefaultFrom);
    m_to->setValue(ConnectRequest::DefaultTo);
    auto *range = new QHBoxLayout;
    range->addWidget(m_from);
    range->addWidget(new QLabel(QStringLiteral("–"), m_scanBox));
    range->addWidget(m_to);
    range->addStretch(1);
    scanForm->addRow(m_rangeLabel, range);
    m_timeout = labelledField<QSpinBox>(m_scanBox, QStringLiteral("probeTimeout"), &m_timeoutLabel);
    m_timeout->setRange(0, 2000); // 0 (shown as "Automatic"): the scanner's adaptive timeout
    m_timeout->setSingleStep(10);
    m_timeout->setValue(ConnectRequest::DefaultProbeTimeoutMs);
    scanForm->addRow(m_timeoutLabel, m_timeout);
    connect(m_from, &QSpinBox::valueChanged, this, [this](int v) { m_to->setMinimum(v); });
}

bool ConnectDialog::isCan() const
{
    return m_canRadio->isChecked();
}

QString ConnectDialog::currentPort() const
{
    const bool listed = m_port->currentIndex() >= 0
        && m_port->currentText() == m_port->itemText(m_port->currentIndex());
    return listed ? m_port->currentData().toString() : m_port->currentText().trimmed();
}

QString ConnectDialog::currentInterface() const
{
    const bool listed = m_interface->currentIndex() >= 0
        && m_interface->currentText() == m_interface->itemText(m_interface->currentIndex());
    return listed ? m_interface->currentData().toString() : m_interface->currentText().trimmed();
}

void ConnectDialog::fillPorts()
{
    setPorts(m_watcher->ports());
}

bool ConnectDialog::offersDemo() const
{
    return !m_noPorts->isHidden();
}

void ConnectDialog::setPorts(const QList<SerialPortEntry> &ports)
{
    m_noPorts->setHidden(!ports.isEmpty());
    const QString current = currentPort().isEmpty() ? m_wantedPort : currentPort();
    m_port->clear();
    for (const SerialPortEntry &e : ports) {
        m_port->addItem(e.label(), e.path);
        m_port->setItemData(m_port->count() - 1, e.label(), Qt::ToolTipRole);
    }
    const int i = m_port->findData(current);
    if (i >= 0)
        m_port->setCurrentIndex(i);
    else if (!current.isEmpty())
        m_port->setEditText(current);
    else if (m_port->count() > 0)
        m_port->setCurrentIndex(0);
}

void ConnectDialog::fillCanPlugins()
{
    const QString current = m_plugin->currentText();
    const QSignalBlocker block(m_plugin);
    m_plugin->clear();
    QStringList plugins = QCanBus::instance()->plugins();
    plugins.sort();
    m_plugin->addItems(plugins);
    const int i = m_plugin->findText(current.isEmpty() ? QStringLiteral("socketcan") : current);
    m_plugin->setCurrentIndex(i >= 0 ? i : 0);
    fillCanInterfaces();
}

void ConnectDialog::fillCanInterfaces()
{
    const QString current = currentInterface().isEmpty() ? m_wantedInterface : currentInterface();
    m_interface->clear();
    m_canError->clear();
    const QString plugin = m_plugin->currentText();
    if (plugin.isEmpty()) {
        m_canError->setText(tr("No CAN plugin is installed."));
        return;
    }
    QString error;
    const QList<QCanBusDeviceInfo> devices = QCanBus::instance()->availableDevices(plugin, &error);
    for (const QCanBusDeviceInfo &d : devices) {
        const QString label = d.description().isEmpty() ? d.name()
                                                        : QStringLiteral("%1 — %2").arg(d.name(), d.description());
        m_interface->addItem(label, d.name());
    }
    if (!error.isEmpty())
        m_canError->setText(tr("%1: %2").arg(plugin, error));
    else if (devices.isEmpty())
        m_canError->setText(tr("The %1 plugin reports no interface; type its name.").arg(plugin));
    const int i = m_interface->findData(current);
    if (i >= 0)
        m_interface->setCurrentIndex(i);
    else if (!current.isEmpty())
        m_interface->setEditText(current);
}

const FamilyTraits *ConnectDialog::selectedTraits() const
{
    const std::optional<Family> f = familyFromId(m_family->currentData().toString());
    return f ? &familyTraits(*f) : nullptr;
}

void ConnectDialog::fillFramings()
{
    const QString current = m_framing->currentData().toString();
    const QSignalBlocker block(m_framing);
    m_framing->clear();
    const LinkKind link = isCan() ? LinkKind::Can : LinkKind::Serial;
    if (const FamilyTraits *traits = selectedTraits()) {
        for (const FramingTraits &f : traits->framings)
            if (f.link == link)
                m_framing->addItem(f.displayName(), f.id);
    }
    selectData(m_framing, current);
}

void ConnectDialog::updateEnabled()
{
    // The framing matters for a family that has several; the scan range is the family's
    // (auto-detect: any family's on this kind of link).
    const FamilyTraits *traits = selectedTraits();
    const bool framings = traits && traits->framings.size() > 1;
    m_framing->setEnabled(framings);
    m_framingLabel->setEnabled(framings);
    m_sweep->setEnabled(!isCan());
    const LinkKind link = isCan() ? LinkKind::Can : LinkKind::Serial;
    AddressRange range{-1, -1};
    for (const FamilyTraits *t : allFamilyTraits()) {
        if (traits && t != traits)
            continue;
        const AddressRange r = t->addresses(link);
        if (r.first < 0)
            continue;
        range.first = range.first < 0 ? r.first : qMin(range.first, r.first);
        range.last = qMax(range.last, r.last);
    }
    if (range.first >= 0) {
        m_from->setRange(range.first, range.last);
        m_to->setRange(qMax(range.first, m_from->value()), range.last);
    }
}

void ConnectDialog::setRequest(const ConnectRequest &r)
{
    m_canRadio->setChecked(r.settings.isCan());
    m_serialRadio->setChecked(!r.settings.isCan());
    m_wantedPort = r.settings.port;
    fillPorts();
    const int pi = m_port->findData(r.settings.port);
    if (pi >= 0)
        m_port->setCurrentIndex(pi);
    else
        m_port->setEditText(r.settings.port);
    selectData(m_baud, r.settings.baud);
    m_sweep->setChecked(r.sweepBauds);
    CanSettings can;
    if (CanSettings::parse(r.settings.can, &can)) {
        m_wantedInterface = can.interface;
        const int i = m_plugin->findText(can.plugin);
        if (i >= 0)
            m_plugin->setCurrentIndex(i);
        fillCanInterfaces();
        const int ii = m_interface->findData(can.interface);
        if (ii >= 0)
            m_interface->setCurrentIndex(ii);
        else
            m_interface->setEditText(can.interface);
    }
    selectData(m_bitrate, r.settings.bitrate);
    selectData(m_family, r.detect ? DetectId : familyId(r.settings.family));
    fillFramings();
    selectData(m_framing, r.settings.framing);
    updateEnabled();
    m_scanBox->setChecked(r.scan);
    m_from->setValue(r.scanOptions.from);
    m_to->setValue(r.scanOptions.to);
    m_timeout->setValue(r.scanOptions.timeoutMs <= 0 ? 0 : r.scanOptions.timeoutMs);
    updateEnabled();
}

ConnectRequest ConnectDialog::request() const
{
    ConnectRequest r;
    const QString family = m_family->currentData().toString();
    r.detect = family == DetectId;
    r.settings.family = familyFromId(family).value_or(Family::ServoModbus);
    if (isCan()) {
        r.settings.can = QStringLiteral("%1:%2").arg(m_plugin->currentText(), currentInterface());
        r.settings.bitrate = m_bitrate->currentData().toInt();
    } else {
        r.settings.port = currentPort();
        r.settings.baud = m_baud->currentData().toInt();
        r.sweepBauds = m_sweep->isChecked();
    }
    if (!r.detect && familyTraits(r.settings.family).framings.size() > 1)
        r.settings.framing = m_framing->currentData().toString();
    r.scan = m_scanBox->isChecked();
    r.scanOptions.from = m_from->value();
    r.scanOptions.to = m_to->value();
    r.scanOptions.timeoutMs = m_timeout->value() > 0 ? m_timeout->value() : -1;
    return r;
}

void ConnectDialog::loadSettings()
{
    QSettings s;
    setRequest(ConnectRequest::load(s));
}

void ConnectDialog::saveSettings() const
{
    QSettings s;
    request().save(s);
}

void ConnectDialog::accept()
{
    const ConnectRequest r = request();
    QString problem;
    if (!r.settings.isCan() && r.settings.port.isEmpty())
        problem = tr("Choose a serial port, or type its name.");
    else if (r.settings.isCan() && (m_plugin->currentText().isEmpty() || r.settings.can.endsWith(QLatin1Char(':'))))
        problem = tr("Choose a CAN plugin and an interface.");
    if (!problem.isEmpty()) {
        QMessageBox::warning(this, windowTitle(), problem);
        return;
    }
    saveSettings();
    QDialog::accept();
}

void ConnectDialog::showEvent(QShowEvent *event)
{
    m_watcher->start();
    fillPorts(); // also when the list did not change (none at all: the demo bench is offered)
    QDialog::showEvent(event);
}

void ConnectDialog::hideEvent(QHideEvent *event)
{
    m_watcher->stop();
    QDialog::hideEvent(event);
}

void ConnectDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ConnectDialog::retranslate()
{
    setWindowTitle(tr("Connect"));
    m_linkBox->setTitle(tr("Link"));
    m_serialRadio->setText(tr("&Serial port (RS485 / RS232)"));
    m_canRadio->setText(tr("C&AN bus"));
    m_portLabel->setText(tr("&Port:"));
    m_port->setToolTip(tr("Adapters are listed as they are plugged in. Virtual ports: links to "
                          "pseudo-terminals in the temp directory (drivedesk-sim --link)."));
    m_baudLabel->setText(tr("&Baud rate:"));
    m_baud->setItemText(0, tr("Family default"));
    m_sweep->setText(tr("Try all common baud rates when scanning"));
    m_noPortsText->setText(tr("No serial port was found. Plug in the USB adapter (it appears here within a "
                              "second), or try DriveDesk on simulated drives."));
    m_demo->setText(tr("Start the &demo bench"));
    m_pluginLabel->setText(tr("P&lugin:"));
    m_interfaceLabel->setText(tr("&Interface:"));
    m_refreshCan->setText(tr("Refresh"));
    m_bitrateLabel->setText(tr("Bi&trate:"));
    m_bitrate->setItemText(0, tr("Family default"));
    for (int i = 1; i < m_bitrate->count(); ++i)
        m_bitrate->setItemText(i, tr("%1 kbit/s").arg(m_bitrate->itemData(i).toInt() / 1000));
    m_driveBox->setTitle(tr("Drive"));
    m_familyLabel->setText(tr("&Family:"));
    m_framingLabel->setText(tr("F&raming:"));
    m_framing->setToolTip(tr("Shuoke drives only: how the drive is set to talk"));

    const QString family = m_family->currentData().toString();
    {
        const QSignalBlocker block(m_family);
        m_family->clear();
        m_family->addItem(tr("Detect automatically"), DetectId);
        for (const FamilyTraits *t : allFamilyTraits())
            m_family->addItem(QStringLiteral("%1 (%2)").arg(t->displayName(), t->id()), t->id());
        selectData(m_family, family.isEmpty() ? DetectId : family);
    }
    m_family->setToolTip(tr("Detect tries each family in turn (serial: servo-modbus, then shuoke "
                            "RTU and ASCII; CAN: servo-can, then shuoke) and keeps the first that "
                            "finds a drive."));
    fillFramings();
    m_scanBox->setTitle(tr("S&can for drives after connecting"));
    m_rangeLabel->setText(tr("Addresses:"));
    m_timeoutLabel->setText(tr("Probe ti&meout:"));
    m_timeout->setSuffix(tr(" ms"));
    m_timeout->setSpecialValueText(tr("Automatic (fast, direct RS485 only)"));
    m_timeout->setToolTip(tr("How long to wait for each address to answer. USB adapters add up "
                             "to 16 ms of latency: keep 50 ms or more unless the port is a "
                             "native RS485 interface."));
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("C&onnect"));
    m_buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));
}

} // namespace dd

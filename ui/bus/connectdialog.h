#pragma once

#include "ui/bus/connectrequest.h"
#include "ui/bus/serialportentry.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QStackedWidget;

namespace dd {

class SerialPortWatcher;

// File → Connect: the link (a serial port with its baud rate, or a CAN plugin, interface
// and bitrate), the family or "detect", the shuoke framing, and the address range to scan.
// Serial ports are listed with description, manufacturer and USB VID:PID and refreshed
// while the dialog is open (see SerialPortWatcher: polled once a second); CAN interfaces
// are listed per plugin (QCanBus::availableDevices) when the plugin changes or on Refresh.
// The last settings are loaded from and saved to QSettings.
class ConnectDialog : public QDialog
{
    Q_OBJECT
public:
    // exec()'s result when the user chose "Start the demo bench" (offered when no serial port
    // is found).
    static constexpr int DemoRequested = 2;

    explicit ConnectDialog(QWidget *parent = nullptr);

    void setRequest(const ConnectRequest &request);
    ConnectRequest request() const;

    // Loads / saves the last settings (QSettings "connect" group).
    void loadSettings();
    void saveSettings() const;

    SerialPortWatcher *portWatcher() const { return m_watcher; }
    QComboBox *portCombo() const { return m_port; }
    // Lists these serial ports (the watcher's list); with none, says so and offers the demo
    // bench instead.
    void setPorts(const QList<SerialPortEntry> &ports);
    bool offersDemo() const;

    void accept() override;

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void buildLinkBox();
    QWidget *createSerialPage();
    QWidget *createCanPage();
    void buildDriveBox();
    void buildScanBox();
    void fillPorts();
    void fillCanPlugins();
    void fillCanInterfaces();
    const FamilyTraits *selectedTraits() const; // nullptr: auto-detect
    void fillFramings();
    void updateEnabled();
    void retranslate();
    bool isCan() const;
    QString currentPort() const;
    QString currentInterface() const;

    SerialPortWatcher *m_watcher = nullptr;
    QGroupBox *m_linkBox = nullptr;
    QRadioButton *m_serialRadio = nullptr;
    QRadioButton *m_canRadio = nullptr;
    QStackedWidget *m_linkPages = nullptr;
    // Serial.
    QLabel *m_portLabel = nullptr;
    QComboBox *m_port = nullptr;
    QLabel *m_baudLabel = nullptr;
    QComboBox *m_baud = nullptr;
    QCheckBox *m_sweep = nullptr;
    QWidget *m_noPorts = nullptr;
    QLabel *m_noPortsText = nullptr;
    QPushButton *m_demo = nullptr;
    // CAN.
    QLabel *m_pluginLabel = nullptr;
    QComboBox *m_plugin = nullptr;
    QLabel *m_interfaceLabel = nullptr;
    QComboBox *m_interface = nullptr;
    QPushButton *m_refreshCan = nullptr;
    QLabel *m_bitrateLabel = nullptr;
    QComboBox *m_bitrate = nullptr;
    QLabel *m_canError = nullptr;
    // Drive.
    QGroupBox *m_driveBox = nullptr;
    QLabel *m_familyLabel = nullptr;
    QComboBox *m_family = nullptr;
    QLabel *m_framingLabel = nullptr;
    QComboBox *m_framing = nullptr;
    // Scan.
    QGroupBox *m_scanBox = nullptr;
    QLabel *m_rangeLabel = nullptr;
    QSpinBox *m_from = nullptr;
    QSpinBox *m_to = nullptr;
    QLabel *m_timeoutLabel = nullptr;
    QSpinBox *m_timeout = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    QString m_wantedPort; // a remembered port not (yet) in the list
    QString m_wantedInterface;
};

} // namespace dd

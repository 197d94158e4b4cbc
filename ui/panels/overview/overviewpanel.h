#pragma once

#include "ui/workspace/drivepanel.h"

class QFormLayout;
class QGroupBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace dd {

// The first tab of every drive: who it is (family, address, model, firmware, link), what
// it can do (each capability, and why not when it cannot) and its live state.
class OverviewPanel : public DrivePanel
{
    Q_OBJECT
public:
    explicit OverviewPanel(const DriveContext &context, QWidget *parent = nullptr);

    QString panelId() const override { return QStringLiteral("overview"); }
    QString title() const override;

    // Asks the drive again for its identity and status.
    void refresh();

protected:
    void driveInfoChanged(const DriveInfo &info) override;
    void statusChanged(const DriveStatus &status) override;
    void alarmChanged(int code) override;
    void retranslate() override;

private:
    void showIdentity();
    void showCapabilities();
    void showStatus();

    QGroupBox *m_identityBox = nullptr;
    QGroupBox *m_statusBox = nullptr;
    QGroupBox *m_capsBox = nullptr;
    QFormLayout *m_identityForm = nullptr;
    QFormLayout *m_statusForm = nullptr;
    QList<QLabel *> m_identityLabels;
    QList<QLabel *> m_statusLabels;
    QLabel *m_family = nullptr;
    QLabel *m_address = nullptr;
    QLabel *m_model = nullptr;
    QLabel *m_firmware = nullptr;
    QLabel *m_link = nullptr;
    QLabel *m_online = nullptr;
    QLabel *m_motion = nullptr;
    QLabel *m_enabled = nullptr;
    QLabel *m_position = nullptr;
    QLabel *m_alarm = nullptr;
    QLabel *m_updated = nullptr;
    QTableWidget *m_caps = nullptr;
    QLabel *m_reasons = nullptr;
    QPushButton *m_refresh = nullptr;
};

} // namespace dd

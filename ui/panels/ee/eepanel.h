#pragma once

#include "ui/workspace/drivepanel.h"

#include <QElapsedTimer>
#include <QMap>
#include <QTimer>
#include <optional>

class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace dd {

// The EEPROM tab (servo-modbus: Capability::EeOperations): the five EE operations, each
// with its mnemonic, its meaning and what it does to the drive's values. The destructive
// ones (reload, restore the backup area, factory defaults) ask for confirmation first.
// While one runs, a progress bar and the elapsed time show until the drive reports
// completion (the legacy format is polled until then). On a drive without the capability
// the buttons are disabled and the reason is shown.
class EePanel : public DrivePanel
{
    Q_OBJECT
public:
    explicit EePanel(const DriveContext &context, QWidget *parent = nullptr);

    QString panelId() const override { return QStringLiteral("ee"); }
    QString title() const override;

    // Runs `op` (after confirmation when it is destructive).
    void runOperation(EeOperation op);
    bool isBusy() const { return m_running.has_value(); }
    QString message() const;
    QPushButton *button(EeOperation op) const { return m_buttons.value(op); }

    // What the operation does to the drive's values (translated).
    static QString explanation(EeOperation op);
    static QList<EeOperation> operations();

signals:
    void operationStarted(dd::EeOperation op);
    void operationFinished(dd::EeOperation op, bool ok);

protected:
    void driveInfoChanged(const DriveInfo &info) override;
    void retranslate() override;

private:
    bool confirm(EeOperation op);
    void onFinished(EeOperation op, const DriveResult &result);
    void updateElapsed();
    void updateActions();
    void setMessage(const QString &text, MessageKind kind);

    QLabel *m_intro = nullptr;
    QGroupBox *m_box = nullptr;
    QMap<EeOperation, QPushButton *> m_buttons;
    QMap<EeOperation, QLabel *> m_meanings;
    QMap<EeOperation, QLabel *> m_explanations;
    QLabel *m_reason = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_message = nullptr;
    std::optional<EeOperation> m_running;
    QElapsedTimer m_clock;
    QTimer m_tick;
};

} // namespace dd

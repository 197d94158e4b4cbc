#pragma once

#include "core/trend/trendchannel.h"

#include <QColor>
#include <QHash>
#include <QWidget>

class QCheckBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;

namespace dd {

// The channel list beside a trend plot: per channel a check box (shown or hidden, in the
// series colour), a scale factor and an offset. The plot draws value × scale + offset, so
// channels of very different magnitude (speed in r/min, current in A) can share one axis;
// readouts and exports always use the real values.
class TrendChannelPanel : public QWidget
{
    Q_OBJECT
public:
    struct Settings
    {
        bool visible = true;
        double scale = 1.0;
        double offset = 0.0;
    };

    explicit TrendChannelPanel(QWidget *parent = nullptr);

    // Rebuilds the rows; settings of ids seen before are kept.
    void setChannels(const QList<TrendChannel> &channels, const QList<QColor> &colors);
    Settings settings(const QString &id) const { return m_settings.value(id); }
    void setChannelVisible(const QString &id, bool visible);
    void setChannelScale(const QString &id, double scale, double offset);
    QCheckBox *checkBox(const QString &id) const;

signals:
    void visibilityChanged(const QString &id, bool visible);
    void scaleChanged(const QString &id, double scale, double offset);

protected:
    void changeEvent(QEvent *event) override;

private:
    struct Row
    {
        QCheckBox *check = nullptr;
        QDoubleSpinBox *scale = nullptr;
        QDoubleSpinBox *offset = nullptr;
    };
    void retranslateUi();

    QGridLayout *m_grid;
    QLabel *m_scaleHeader;
    QLabel *m_offsetHeader;
    QList<TrendChannel> m_channels;
    QHash<QString, Row> m_rows;
    QHash<QString, Settings> m_settings;
};

} // namespace dd

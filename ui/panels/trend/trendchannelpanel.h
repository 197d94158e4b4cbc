#pragma once

#include "core/trend/trendchannel.h"

#include <QColor>
#include <QHash>
#include <QWidget>

class QListWidget;
class QListWidgetItem;
class QMenu;
class QToolButton;

namespace dd {

// The compact channel list beside a trend plot: one checkable line per channel (shown or
// hidden, a swatch in the series colour, the name elided with the full label in its
// tooltip). Each channel's menu (right click, or the "Channel" button for the current
// line) assigns it to the left or the right value axis and sets a scale and an offset:
// the plot draws value × scale + offset, readouts and exports always use real values.
// Channels get an axis by unit when first seen: the first channel's unit on the left,
// any other unit on the right.
class TrendChannelPanel : public QWidget
{
    Q_OBJECT
public:
    struct Settings
    {
        bool visible = true;
        double scale = 1.0;
        double offset = 0.0;
        int axis = 0; // TrendPlot::Left / Right
    };

    explicit TrendChannelPanel(QWidget *parent = nullptr);

    // Rebuilds the list; settings of ids seen before are kept.
    void setChannels(const QList<TrendChannel> &channels);
    void setColors(const QHash<QString, QColor> &colors);
    Settings settings(const QString &id) const { return m_settings.value(id); }
    void setChannelVisible(const QString &id, bool visible);
    void setChannelScale(const QString &id, double scale, double offset);
    void setChannelAxis(const QString &id, int axis);

    QListWidget *list() const { return m_list; }
    QListWidgetItem *item(const QString &id) const;
    // The menu of a channel (axis, scale and offset), as the user gets it.
    QMenu *menuFor(const QString &id);

signals:
    void visibilityChanged(const QString &id, bool visible);
    void scaleChanged(const QString &id, double scale, double offset);
    void axisChanged(const QString &id, int axis);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void updateItem(const QString &id);
    void editScale(const QString &id);

    QListWidget *m_list;
    QToolButton *m_menuButton;
    QMenu *m_menu = nullptr;
    QList<TrendChannel> m_channels;
    QHash<QString, Settings> m_settings;
    QHash<QString, QColor> m_colors;
    bool m_filling = false;
};

} // namespace dd

#pragma once

#include "cli/clicommand.h"

#include "core/trend/csvwriter.h"

#include <QTimer>

namespace dd {

class ChannelSampler;

// monitor CHANNEL,... [--rate HZ] [--duration S] [-o FILE.csv]
// Without --rate it samples as fast as the link carries the channels (LinkRate, as the GUI
// trend does); the rate used is in the JSON summary ("rateHz").
class MonitorCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit MonitorCommand(CliContext *c);
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int signalNumber) override;

private:
    void onSample(double timeS, const QMap<QString, double> &values);
    void end(const Error &error);
    QString textRow(const QStringList &cells) const;

    QStringList m_channelIds;

    QList<int> m_columnWidths; // text output: from the header
    QList<ChannelInfo> m_channels;
    double m_rateHz = 0.0;    // 0: the link's rate (LinkRate), chosen when the drive is open
    double m_durationS = 0.0; // 0: until Ctrl-C
    QString m_csvPath;
    CsvWriter m_csv;
    ChannelSampler *m_sampler = nullptr;
    QTimer m_duration;
};

} // namespace dd

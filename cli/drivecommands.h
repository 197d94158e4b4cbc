#pragma once

#include "cli/clicommand.h"

// Commands that ask the drive one thing: info, channels, stop, enable, clear-alarm.

namespace dd {

class InfoCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit InfoCommand(CliContext *c)
        : CliCommand(QStringLiteral("info"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    bool identifyFirst() const override { return false; } // start() does
    void start() override;

private:
    void report();
    DriveStatus m_status;
    QStringList m_warnings;
};

class ChannelsCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit ChannelsCommand(CliContext *c)
        : CliCommand(QStringLiteral("channels"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    bool identifyFirst() const override { return false; } // start() does
    void start() override;
};

class StopCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit StopCommand(CliContext *c)
        : CliCommand(QStringLiteral("stop"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int) override { } // a stop is never abandoned half-way
    bool identifyMayFail() const override { return true; }

private:
    bool m_emergency = false;
};

class EnableCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit EnableCommand(CliContext *c)
        : CliCommand(QStringLiteral("enable"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;

private:
    bool m_on = false;
};

class ClearAlarmCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit ClearAlarmCommand(CliContext *c)
        : CliCommand(QStringLiteral("clear-alarm"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
};

} // namespace dd

#pragma once

#include "core/link/connectionsettings.h"
#include "core/link/trafficrecord.h"
#include "sim/shuoke/simshuokedrive.h"

#include <QDebug>
#include <QList>
#include <QObject>
#include <memory>

namespace dd {

class DriveConnection;
class ShuokeBackend;
class ShuokeDrive;

// The host side of the Shuoke integration benches (ShuokeSerialBench, ShuokeCanBench): a
// DriveConnection with the real ShuokeBackend, and every frame its TrafficTap records.
class ShuokeHostBench : public QObject
{
    Q_OBJECT
public:
    explicit ShuokeHostBench(QObject *parent = nullptr);
    ~ShuokeHostBench() override;

    DriveConnection *connection() const { return m_connection.get(); }
    ShuokeBackend *backend() const;
    ShuokeDrive *drive(int address) const;

    const QList<TrafficRecord> &records() const { return m_records; }
    void clearRecords() { m_records.clear(); }
    int txCount() const;

protected:
    // The create() of a bench: a started Bench with `drives` on its bus (addDrive(config,
    // extra...)) and the host connected with `settings`; nullptr, with a warning saying
    // why, when a step fails.
    template <typename Bench, typename... Extra>
    static std::unique_ptr<Bench> createBench(const QList<SimShuokeDrive::Config> &drives,
                                              const ConnectionSettings &settings, Extra... extra)
    {
        auto bench = std::make_unique<Bench>();
        QString error;
        if (!bench->start(&error)) {
            qWarning() << error;
            return nullptr;
        }
        for (const SimShuokeDrive::Config &c : drives)
            bench->addDrive(c, extra...);
        if (!bench->connectHost(settings, &error)) {
            qWarning() << error;
            return nullptr;
        }
        return bench;
    }

    // Opens the host side for the shuoke family; false (and `error`) when it cannot.
    bool openHost(ConnectionSettings settings, QString *error);
    // Closes it (before the simulated bus goes away).
    void closeHost();

private:
    std::unique_ptr<DriveConnection> m_connection;
    QList<TrafficRecord> m_records;
};

} // namespace dd

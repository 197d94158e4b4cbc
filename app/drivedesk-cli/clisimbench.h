#pragma once

#include "cliglobals.h"
#include "common/error.h"

#include <QObject>

namespace dd {

class SimCanBus;
class SimSerialBus;
class VirtualCanHub;

// `--sim`: simulated drives in this process, reached through the production link code.
// Serial families: a SimSerialBus on a pseudo-terminal (the CLI's QSerialPort opens the
// pty). CAN: a private virtualcan hub on a free local port (so that nothing else on the
// machine shares the bus) and a SimCanBus on it. start() rewrites the connection settings
// to point at the bench.
class CliSimBench : public QObject
{
    Q_OBJECT
public:
    explicit CliSimBench(QObject *parent = nullptr);
    ~CliSimBench() override;

    // Drives: `globals.simDrives`, or one at `globals.address` at `globals`' baud.
    // OpenFailed / NotSupported when the bench cannot be built.
    Error start(CliGlobals *globals);
    QString description() const { return m_description; }

    // The baud a simulated serial drive uses when none is given.
    static int defaultBaud(Family family);

private:
    Error startSerial(CliGlobals *globals);
    Error startCan(CliGlobals *globals);

    SimSerialBus *m_serial = nullptr;
    VirtualCanHub *m_hub = nullptr;
    SimCanBus *m_can = nullptr;
    QString m_description;
};

} // namespace dd

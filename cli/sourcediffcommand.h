#pragma once

#include "cli/clicommand.h"

#include "core/fleet/parametersource.h"

#include <QList>
#include <memory>

namespace dd {

class FleetTransfer;
class ParameterDictionary;

// diff A B: each of A and B is a backup file, `drive` (the drive at --address),
// `drive:ADDRESS` or `defaults` (the dictionary's). Exit code as diff(1): 0 equal,
// 1 different, 2 trouble (bad input — nothing sent —, or a drive that did not answer),
// 3 the port could not be opened. Sources of different families are refused (2).
class SourceDiffCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit SourceDiffCommand(CliContext *c)
        : CliCommand(QStringLiteral("diff"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    bool needsLink() const override { return !m_driveAddresses.isEmpty(); }
    bool needsDrive() const override { return false; }
    void start() override;
    // Whether one of the arguments names a drive (then the link is needed).
    static bool namesADrive(const QStringList &arguments);

protected:
    CliExit exitForFailure(const Error &error) const override;

private:
    struct Spec
    {
        ParameterSource::Kind kind = ParameterSource::Kind::Defaults;
        int address = -1;
        QString path;
        ParameterSource source; // files and defaults: ready after prepare()
    };
    bool parseSpec(const QString &text, Spec *spec, QString *error) const;
    void compare();

    QList<Spec> m_specs;
    QList<int> m_driveAddresses;
    std::shared_ptr<const ParameterDictionary> m_dictionary;
    FleetTransfer *m_transfer = nullptr;
};

} // namespace dd

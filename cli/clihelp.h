#pragma once

#include <QCoreApplication>
#include <QString>

namespace dd {

// The texts of `drivedesk-cli --help` and `drivedesk-cli COMMAND --help`.
class CliHelp
{
    Q_DECLARE_TR_FUNCTIONS(dd::Cli)
public:
    static QString general();
    static QString command(const QString &name);

private:
    // The sections of general().
    static QString usage();
    static QString linkOptions();
    static QString outputOptions();
    static QString commandList();
    static QString exitCodes();
    static QString simulator();
    static QString examples();
};

} // namespace dd

#pragma once

#include "cli/cliparser.h"
#include "core/link/connectionsettings.h"
#include "core/protocol/familytraits.h"

#include <QCoreApplication>

namespace dd {

// The global options, interpreted: which family, which link, which drive, how to print.
struct CliGlobals
{
    Q_DECLARE_TR_FUNCTIONS(dd::Cli)
public:
    ConnectionSettings connection;
    bool addressGiven = false;
    int address = 1;
    // --address 1,2,5: every address given, in order (one entry for a single --address;
    // empty without --address). Only the commands that work on several drives take more.
    QList<int> addresses;
    // Set before load() for a command that may run without a link (diff of two files).
    bool linkOptional = false;
    bool json = false;
    bool trace = false;
    QString dictionaryFile;
    QString machine; // --machine NAME: keys the verification journal (JournalKey::machine)
    bool sim = false;
    // --sim-drives ADDR[@BAUD],...: the simulated drives (empty: one at `address`).
    struct SimDrive
    {
        int address = 1;
        int baud = 0;
    };
    QList<SimDrive> simDrives;
    bool simMotion = false;      // --sim-motion: the simulated drives move on their own
    double simResonanceHz = 0.0; // --sim-resonance-hz F: a compliant load resonating at F
    QString simStateFile;        // --sim-state FILE: the bench's state, loaded and saved
    QString simDescription;      // set once the bench runs

    // The option table (for the parser and the help).
    static QList<CliOptionSpec> optionSpecs();
    // Interprets and checks the global options; false with a translated message.
    bool load(const CliInvocation &inv, QString *error);
    // Whether the link is a CAN bus (also with --sim, before the bench has named it).
    bool isCanLink() const;
    // The address a command talks to when --address is not given (as drivedesk-sim's).
    static int defaultAddress(Family family);
    // The addresses a drive of the family can have on this link and framing (the traits').
    AddressRange addressRange() const;

private:
    bool loadFlags(const CliInvocation &inv, QString *error);
    bool loadLink(const CliInvocation &inv, QString *error);
    bool loadFamily(const CliInvocation &inv, QString *error);
    bool loadNumbers(const CliInvocation &inv, QString *error);
    bool loadOptions(const CliInvocation &inv, QString *error);
    bool loadAddress(const CliInvocation &inv, QString *error);
    bool loadSimDrives(const CliInvocation &inv, QString *error);
};

} // namespace dd

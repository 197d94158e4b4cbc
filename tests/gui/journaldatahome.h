#pragma once
// For the GUI tests of the write paths: a data folder (XDG_DATA_HOME, so GenericDataLocation)
// of the test's own while it lives, and the verification journal the GUI keeps there for a
// drive (ui/report/guijournal.h), read as the commissioning record reads it.

#include "core/drive/drivehub.h"
#include "core/report/verificationjournal.h"
#include "ui/report/guijournal.h"

#include <QTemporaryDir>
#include <QtGlobal>

namespace dd::test {

class JournalDataHome
{
public:
    JournalDataHome()
        : m_old(qgetenv("XDG_DATA_HOME"))
        , m_hadOld(qEnvironmentVariableIsSet("XDG_DATA_HOME"))
    {
        qputenv("XDG_DATA_HOME", m_dir.path().toUtf8());
    }
    ~JournalDataHome()
    {
        if (m_hadOld)
            qputenv("XDG_DATA_HOME", m_old);
        else
            qunsetenv("XDG_DATA_HOME");
    }
    JournalDataHome(const JournalDataHome &) = delete;
    JournalDataHome &operator=(const JournalDataHome &) = delete;

    // The journal of the drive at (`connectionId`, `address`) that identified itself as `identity`.
    static VerificationJournal::Entry read(const DriveHub *hub, int connectionId, int address,
                                           const DriveIdentity &identity)
    {
        return VerificationJournal().read(GuiJournal::key(hub, connectionId, address, identity));
    }

private:
    QTemporaryDir m_dir;
    QByteArray m_old;
    bool m_hadOld = false;
};

} // namespace dd::test

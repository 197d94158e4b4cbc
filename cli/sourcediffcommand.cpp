#include "cli/sourcediffcommand.h"

#include "cli/backupcommands.h"
#include "cli/clidescribe.h"
#include "cli/clivalues.h"

#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h" // driveconnection.h needs it complete (QPointer)
#include "core/fleet/fleettransfer.h"
#include "core/fleet/parametercomparison.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"

#include <QFileInfo>
#include <QJsonArray>

namespace dd {

namespace {

bool isDriveSpec(const QString &text)
{
    return text == QLatin1String("drive") || text.startsWith(QLatin1String("drive:"));
}

} // namespace

bool SourceDiffCommand::namesADrive(const QStringList &arguments)
{
    return std::any_of(arguments.begin(), arguments.end(), isDriveSpec);
}

CliExit SourceDiffCommand::exitForFailure(const Error &error) const
{
    return diffExitForFailure(error);
}

bool SourceDiffCommand::parseSpec(const QString &text, Spec *spec, QString *error) const
{
    const CliGlobals &g = context()->globals;
    if (text == QLatin1String("defaults")) {
        spec->kind = ParameterSource::Kind::Defaults;
        return true;
    }
    if (text == QLatin1String("drive")) {
        spec->kind = ParameterSource::Kind::Drive;
        spec->address = g.address;
        return true;
    }
    if (text.startsWith(QLatin1String("drive:"))) {
        const AddressRange range = g.addressRange();
        const auto a = CliValues::integer(text.mid(6), range.first, range.last, tr("diff: the address of %1").arg(text),
                                          error);
        if (!a)
            return false;
        spec->kind = ParameterSource::Kind::Drive;
        spec->address = int(*a);
        return true;
    }
    spec->kind = ParameterSource::Kind::File;
    spec->path = text;
    if (!QFileInfo::exists(text)) {
        *error = tr("diff: %1 is neither a file nor drive, drive:ADDRESS or defaults.").arg(text);
        return false;
    }
    return true;
}

bool SourceDiffCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 2, 2, tr("two sources"), error))
        return false;
    for (const QString &text : inv.positionals) {
        Spec spec;
        if (!parseSpec(text, &spec, error))
            return false;
        if (spec.kind == ParameterSource::Kind::Drive && !m_driveAddresses.contains(spec.address))
            m_driveAddresses << spec.address;
        m_specs << spec;
    }
    // The family: the files' (all the same), else the link's. Everything is checked here,
    // before the link is opened.
    const Family linkFamily = context()->globals.connection.family;
    std::optional<Family> family;
    QString firstFile;
    for (Spec &s : m_specs) {
        if (s.kind != ParameterSource::Kind::File)
            continue;
        BackupFile probe;
        if (Error e = probe.load(s.path)) {
            *error = e.message;
            return false;
        }
        const Family f = probe.family().value_or(linkFamily);
        if (family && *family != f) {
            *error = tr("%1 is a backup of a %2 drive and %3 of a %4 drive: parameters of different families "
                        "have different meanings and are never compared.")
                         .arg(firstFile, familyId(*family), s.path, familyId(f));
            return false;
        }
        family = f;
        firstFile = s.path;
    }
    if (family && *family != linkFamily && !m_driveAddresses.isEmpty()) {
        *error = tr("%1 is a backup of a %2 drive; the drives on this link are %3 drives and are never "
                    "compared with another family. To talk to %2 drives add --family %2.")
                     .arg(firstFile, familyId(*family), familyId(linkFamily));
        return false;
    }
    const Family f = family.value_or(linkFamily);
    if (f == linkFamily && context()->dictionary)
        m_dictionary = context()->dictionary;
    else
        m_dictionary = std::make_shared<ParameterDictionary>(ParameterDictionary::bundled(f));
    for (Spec &s : m_specs) {
        if (s.kind == ParameterSource::Kind::Defaults) {
            s.source = ParameterSource::defaults(*m_dictionary);
        } else if (s.kind == ParameterSource::Kind::File) {
            BackupFile file;
            if (Error e = file.load(s.path, m_dictionary.get())) {
                *error = e.message;
                return false;
            }
            s.source = ParameterSource::file(file, s.path, *m_dictionary);
        }
    }
    return true;
}

void SourceDiffCommand::start()
{
    if (m_driveAddresses.isEmpty())
        return compare();
    QList<Drive *> drives;
    for (int a : std::as_const(m_driveAddresses)) {
        Drive *d = context()->connection->drive(a);
        if (d && d->dictionary() != m_dictionary)
            d->setDictionary(m_dictionary);
        drives << d;
    }
    m_transfer = new FleetTransfer(drives, this);
    connect(m_transfer, &FleetTransfer::finished, this, [this] {
        for (const FleetDriveResult &r : m_transfer->results()) {
            if (r.state == FleetDriveResult::State::Done)
                continue;
            Error e = r.error;
            e.message = tr("drive %1: %2").arg(r.address).arg(e.message);
            return fail(e);
        }
        compare();
    });
    m_transfer->backup();
}

void SourceDiffCommand::compare()
{
    QList<ParameterSource> sources;
    for (const Spec &s : std::as_const(m_specs)) {
        if (s.kind != ParameterSource::Kind::Drive) {
            sources << s.source;
            continue;
        }
        const FleetDriveResult &r = m_transfer->results().at(m_driveAddresses.indexOf(s.address));
        sources << ParameterSource::drive(r.identity.family, r.address, r.identity.firmware, r.identity.model,
                                          r.values);
    }
    if (Error e = ParameterComparison::checkFamilies(sources))
        return fail(e);
    const ParameterComparison c = ParameterComparison::compute(*m_dictionary, sources);
    const ParameterSource &a = sources.at(0);
    const ParameterSource &b = sources.at(1);

    QJsonArray list;
    QList<QPair<QString, QString>> rows;
    int same = 0, different = 0, onlyA = 0, onlyB = 0;
    for (const ParameterComparison::Row &row : c.rows()) {
        const std::optional<qint64> va = row.values.at(0), vb = row.values.at(1);
        QString status;
        if (va && vb) {
            status = row.differs ? QStringLiteral("different") : QStringLiteral("same");
            (row.differs ? different : same) += 1;
        } else {
            status = va ? QStringLiteral("only-in-a") : QStringLiteral("only-in-b");
            (va ? onlyA : onlyB) += 1;
        }
        QJsonObject o{{QStringLiteral("index"), row.index},
                      {QStringLiteral("key"), row.key},
                      {QStringLiteral("status"), status},
                      {QStringLiteral("a"), CliValues::json(va)},
                      {QStringLiteral("b"), CliValues::json(vb)}};
        if (row.communication)
            o.insert(QStringLiteral("communication"), true);
        list.append(o);
        if (status == QLatin1String("same"))
            continue;
        QString what = tr("%1  %2").arg(va ? QString::number(*va) : QStringLiteral("-"),
                                        vb ? QString::number(*vb) : QStringLiteral("-"));
        if (row.communication)
            what += tr(" (communication setting)");
        rows.append({m_dictionary->label(row.index), what});
    }
    auto sourceJson = [](const ParameterSource &s) {
        QJsonObject o{{QStringLiteral("source"), s.id}, {QStringLiteral("kind"), ParameterSource::kindId(s.kind)}};
        if (s.address >= 0)
            o.insert(QStringLiteral("address"), s.address);
        if (!s.firmware.isEmpty())
            o.insert(QStringLiteral("firmware"), s.firmware);
        if (s.changedOnly)
            o.insert(QStringLiteral("changedOnly"), true);
        return o;
    };
    const QJsonObject json{{QStringLiteral("a"), sourceJson(a)},
                           {QStringLiteral("b"), sourceJson(b)},
                           {QStringLiteral("family"), familyId(a.family)},
                           {QStringLiteral("equal"), different == 0},
                           {QStringLiteral("different"), different},
                           {QStringLiteral("same"), same},
                           {QStringLiteral("onlyInA"), onlyA},
                           {QStringLiteral("onlyInB"), onlyB},
                           {QStringLiteral("firmwareDiffers"), c.firmwareDiffers()},
                           {QStringLiteral("parameters"), list}};
    QString text;
    if (!rows.isEmpty()) {
        rows.prepend({QString(), tr("%1  %2").arg(a.label, b.label)});
        text = CliDescribe::table(rows);
    }
    if (c.firmwareDiffers())
        text += tr("Firmware differs: %1 has %2, %3 has %4.\n").arg(a.label, a.firmware, b.label, b.firmware);
    text += tr("%1 differ, %2 same (%3 / %4).").arg(different).arg(same).arg(a.label, b.label);
    succeed(json, text, different > 0 ? CliExit::DriveFailed : CliExit::Ok);
}

} // namespace dd

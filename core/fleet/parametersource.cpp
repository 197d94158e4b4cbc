#include "core/fleet/parametersource.h"

#include "core/fleet/defaultvalues.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"

#include <QFileInfo>

namespace dd {

ParameterSource ParameterSource::defaults(const ParameterDictionary &dictionary)
{
    ParameterSource s;
    s.kind = Kind::Defaults;
    s.family = dictionary.family();
    s.label = tr("defaults");
    s.id = QStringLiteral("defaults");
    s.values = DefaultValues::of(dictionary);
    return s;
}

ParameterSource ParameterSource::file(const BackupFile &file, const QString &path,
                                      const ParameterDictionary &dictionary)
{
    ParameterSource s;
    s.kind = Kind::File;
    s.family = file.family().value_or(dictionary.family());
    s.label = QFileInfo(path).fileName();
    s.id = path;
    s.address = file.address();
    s.firmware = file.firmware();
    s.model = file.model();
    s.changedOnly = file.isChangedOnly();
    s.values = s.changedOnly ? DefaultValues::completed(dictionary, file.values()) : file.values();
    return s;
}

ParameterSource ParameterSource::drive(Family family, int address, const QString &firmware, const QString &model,
                                       const ParameterSet &values)
{
    ParameterSource s;
    s.kind = Kind::Drive;
    s.family = family;
    s.label = tr("drive %1").arg(address);
    s.id = QStringLiteral("drive:%1").arg(address);
    s.address = address;
    s.firmware = firmware;
    s.model = model;
    s.values = values;
    return s;
}

QString ParameterSource::kindId(Kind kind)
{
    switch (kind) {
    case Kind::Drive: return QStringLiteral("drive");
    case Kind::File: return QStringLiteral("file");
    case Kind::Defaults: return QStringLiteral("defaults");
    }
    return {};
}

} // namespace dd

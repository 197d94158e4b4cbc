// Backup-file loader, BackupFile::loadFromJson (core/params/backupfile.h), against the
// bundled dictionary of the file's family.
// Input: the file's bytes (seeds: tests/data/backup/, corpus/fuzz_backupfile/).
// When the load fails on the checksum, the target loads the input a second time with the
// checksum replaced by that of the integer index/value pairs it finds, so that mutations reach
// the checks after the checksum (dictionary, access, range) instead of dying on it.
// Invariants: a failed load leaves the object as it was and says why; a loaded file saves
// (toJson) and that output loads again to the same content.

#include "tests/fuzz/fuzzsupport.h"

#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

using namespace dd;

namespace {

QByteArray withRecomputedChecksum(const QByteArray &json)
{
    QJsonDocument doc = QJsonDocument::fromJson(json);
    if (!doc.isObject())
        return json;
    QJsonObject root = doc.object();
    const QJsonValue list = root.value(QStringLiteral("parameters"));
    if (!list.isArray())
        return json;
    ParameterSet values;
    for (const QJsonValue &v : list.toArray()) {
        const QJsonObject e = v.toObject();
        const double index = e.value(QStringLiteral("index")).toDouble(-1);
        const double value = e.value(QStringLiteral("value")).toDouble(NAN);
        if (index >= 0 && index <= 65535 && index == std::floor(index) && std::fabs(value) < 9.0e15
            && value == std::floor(value))
            values.set(int(index), qint64(value));
    }
    root.insert(QStringLiteral("checksum"), BackupFile::checksum(values));
    return QJsonDocument(root).toJson(QJsonDocument::Compact);
}

bool sameContent(const BackupFile &a, const BackupFile &b)
{
    return a.family() == b.family() && a.address() == b.address() && a.firmware() == b.firmware()
        && a.model() == b.model() && a.link() == b.link() && a.values() == b.values()
        && a.toolVersion() == b.toolVersion() && a.created() == b.created();
}

void check(const QByteArray &json, bool retryWithChecksum)
{
    BackupFile file;
    const BackupFile before = file;
    const Error e = file.loadFromJson(json, QStringLiteral("fuzz.json"));
    if (e) {
        DD_FUZZ_CHECK(!e.message.isEmpty());
        DD_FUZZ_CHECK(sameContent(file, before));
        if (e.code == ErrorCode::ChecksumError && retryWithChecksum) {
            const QByteArray fixed = withRecomputedChecksum(json);
            if (fixed != json)
                check(fixed, false);
        }
        return;
    }
    DD_FUZZ_CHECK(file.family().has_value());
    DD_FUZZ_CHECK(file.address() >= 0 && file.address() <= 255);
    const ParameterDictionary &dict = ParameterDictionary::bundled(*file.family());
    for (const int index : file.values().indices()) {
        const ParameterInfo *p = dict.byIndex(index);
        DD_FUZZ_CHECK(p && p->inRange(*file.values().value(index)));
        DD_FUZZ_CHECK((file.values().entry(index).source == ValueSource::LastWritten)
                      == (p->access == Access::WriteOnly));
    }

    QByteArray saved;
    const Error s = file.toJson(dict, &saved);
    DD_FUZZ_CHECK(!s);
    BackupFile again;
    const Error l = again.loadFromJson(saved, QStringLiteral("saved.json"));
    DD_FUZZ_CHECK(!l);
    DD_FUZZ_CHECK(sameContent(again, file));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    check(QByteArray(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size)), true);
    return 0;
}

#include "core/report/recordjson.h"

#include "core/common/family.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace dd {

namespace {

QJsonValue jsonNumber(const std::optional<qint64> &v)
{
    return v ? QJsonValue(double(*v)) : QJsonValue(QJsonValue::Null);
}

QJsonValue time(const QDateTime &t)
{
    return t.isValid() ? QJsonValue(t.toUTC().toString(Qt::ISODate)) : QJsonValue(QJsonValue::Null);
}

QJsonObject headerJson(const CommissioningRecord &record)
{
    QJsonObject o = record.header.fieldsJson();
    o.insert(QStringLiteral("created"), time(record.header.created));
    o.insert(QStringLiteral("toolVersion"), record.header.toolVersion);
    o.insert(QStringLiteral("computer"), record.header.computer);
    o.insert(QStringLiteral("language"), record.locale.name());
    return o;
}

QJsonValue verificationJson(const RecordVerification &v)
{
    if (v.isEmpty())
        return QJsonValue(QJsonValue::Null);
    QJsonArray entries;
    for (const RecordVerification::Entry &e : v.entries)
        entries.append(QJsonObject{
            {QStringLiteral("index"), e.index},
            {QStringLiteral("key"), e.key},
            {QStringLiteral("requested"), double(e.requested)},
            {QStringLiteral("readBack"), e.hasReadBack ? QJsonValue(double(e.readBack)) : QJsonValue(QJsonValue::Null)},
            {QStringLiteral("outcome"), e.outcome},
            {QStringLiteral("message"), e.message}});
    return QJsonObject{{QStringLiteral("kind"), v.kind},
                       {QStringLiteral("when"), time(v.when)},
                       {QStringLiteral("sourceFile"), v.sourceFile},
                       {QStringLiteral("sourceChecksum"), v.sourceChecksum},
                       {QStringLiteral("passed"), v.passed()},
                       {QStringLiteral("failed"), v.failedCount()},
                       {QStringLiteral("entries"), entries}};
}

QJsonObject runJson(const RunRecord &run)
{
    QJsonArray metrics;
    for (const RunRecord::Metric &m : run.metrics)
        metrics.append(QJsonObject{{QStringLiteral("key"), m.key},
                                   {QStringLiteral("name"), m.name},
                                   {QStringLiteral("value"), m.value ? QJsonValue(*m.value) : QJsonValue()},
                                   {QStringLiteral("unit"), m.unit},
                                   {QStringLiteral("note"), m.note}});
    QJsonArray snapshot;
    for (const RunRecord::SnapshotValue &s : run.snapshot)
        snapshot.append(QJsonObject{{QStringLiteral("key"), s.key},
                                    {QStringLiteral("name"), s.name},
                                    {QStringLiteral("value"), double(s.value)},
                                    {QStringLiteral("unit"), s.unit}});
    const QJsonValue plot = run.plot.isNull() ? QJsonValue(QJsonValue::Null)
                                              : QJsonValue(QJsonObject{{QStringLiteral("width"), run.plot.width()},
                                                                       {QStringLiteral("height"), run.plot.height()}});
    return {{QStringLiteral("title"), run.title},
            {QStringLiteral("file"), run.file},
            {QStringLiteral("checksum"), run.checksum},
            {QStringLiteral("test"), run.test},
            {QStringLiteral("sampling"),
             QJsonObject{{QStringLiteral("samples"), run.samples},
                         {QStringLiteral("meanIntervalMs"), run.meanIntervalMs},
                         {QStringLiteral("gaps"), run.gaps},
                         {QStringLiteral("longestGapMs"), run.longestGapMs}}},
            {QStringLiteral("when"), time(run.when)},
            {QStringLiteral("metrics"), metrics},
            {QStringLiteral("snapshot"), snapshot},
            {QStringLiteral("plot"), plot}};
}

QJsonObject driveJson(const DriveRecord &d)
{
    QJsonArray parameters;
    for (const RecordParameter &p : d.parameters)
        parameters.append(QJsonObject{{QStringLiteral("index"), p.index},
                                      {QStringLiteral("key"), p.key},
                                      {QStringLiteral("name"), p.name},
                                      {QStringLiteral("unit"), p.unit},
                                      {QStringLiteral("value"), jsonNumber(p.value)},
                                      {QStringLiteral("default"), jsonNumber(p.defaultValue)},
                                      {QStringLiteral("differs"), p.differsFromDefault()}});
    QJsonArray alarms;
    for (const RecordAlarm &a : d.alarms)
        alarms.append(QJsonObject{{QStringLiteral("when"), time(a.when)},
                                  {QStringLiteral("code"), a.code},
                                  {QStringLiteral("text"), a.text},
                                  {QStringLiteral("source"), a.source},
                                  {QStringLiteral("cleared"), a.cleared}});
    const RecordLinkHealth &h = d.linkHealth;
    const QJsonValue turnaround = h.answered > 0
        ? QJsonValue(QJsonObject{{QStringLiteral("min"), h.turnaroundMinMs},
                                 {QStringLiteral("median"), h.turnaroundMedianMs},
                                 {QStringLiteral("max"), h.turnaroundMaxMs}})
        : QJsonValue(QJsonValue::Null);
    const QJsonObject health{{QStringLiteral("measured"), h.measured},
                             {QStringLiteral("scope"), h.scope},
                             {QStringLiteral("requests"), h.requests},
                             {QStringLiteral("answered"), h.answered},
                             {QStringLiteral("turnaroundMs"), turnaround},
                             {QStringLiteral("timeouts"), h.timeouts},
                             {QStringLiteral("checksumErrors"), h.checksumErrors},
                             {QStringLiteral("lateReplies"), h.lateReplies},
                             {QStringLiteral("retries"), h.retries},
                             {QStringLiteral("busyLineSends"), h.busyLineSends},
                             {QStringLiteral("errors"), h.errors}};
    QJsonArray runs;
    for (const RunRecord &r : d.runs)
        runs.append(runJson(r));
    QJsonArray backups;
    for (const BackupReference &b : d.backups)
        backups.append(QJsonObject{{QStringLiteral("role"), b.role},
                                   {QStringLiteral("path"), b.path},
                                   {QStringLiteral("checksum"), b.checksum},
                                   {QStringLiteral("when"), time(b.when)}});
    return {{QStringLiteral("family"), familyId(d.family)},
            {QStringLiteral("address"), d.address},
            {QStringLiteral("firmware"), d.firmware},
            {QStringLiteral("model"), d.model},
            {QStringLiteral("link"), d.link},
            {QStringLiteral("linkSettings"), d.linkSettings},
            {QStringLiteral("identification"), d.identification},
            {QStringLiteral("journalError"), d.journalError},
            {QStringLiteral("readError"), d.readError},
            {QStringLiteral("nonDefault"), int(d.nonDefault().size())},
            {QStringLiteral("withoutDefault"), d.withoutDefault()},
            {QStringLiteral("parameters"), parameters},
            {QStringLiteral("verification"), verificationJson(d.verification)},
            {QStringLiteral("eeOperation"),
             d.eeOperation.isEmpty() ? QJsonValue(QJsonValue::Null)
                                     : QJsonObject{{QStringLiteral("operation"), d.eeOperation.operation},
                                                   {QStringLiteral("when"), time(d.eeOperation.when)},
                                                   {QStringLiteral("ok"), d.eeOperation.ok},
                                                   {QStringLiteral("message"), d.eeOperation.message}}},
            {QStringLiteral("alarms"), alarms},
            {QStringLiteral("linkHealth"), health},
            {QStringLiteral("runs"), runs},
            {QStringLiteral("backups"), backups}};
}

} // namespace

QString RecordJson::formatName()
{
    return QStringLiteral("drivedesk-record");
}

QByteArray RecordJson::toJson(const CommissioningRecord &record)
{
    QJsonArray drives;
    for (const DriveRecord &d : record.drives)
        drives.append(driveJson(d));
    const QJsonObject root{{QStringLiteral("format"), formatName()},
                           {QStringLiteral("formatVersion"), FormatVersion},
                           {QStringLiteral("header"), headerJson(record)},
                           {QStringLiteral("drives"), drives}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

QString RecordJson::sha256(const QByteArray &json)
{
    return QString::fromLatin1(QCryptographicHash::hash(json, QCryptographicHash::Sha256).toHex());
}

} // namespace dd

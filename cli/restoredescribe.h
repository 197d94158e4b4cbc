#pragma once

#include "core/drive/restorereport.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

namespace dd {

class ParameterDictionary;

// How the CLI shows a restore report: the same for `restore` of one drive and the section
// of each drive of `restore --all`.
class RestoreDescribe
{
    Q_DECLARE_TR_FUNCTIONS(dd::RestoreCommand)
public:
    // The selected parameters: JSON entries (index, key, from, to, result, readBack) and
    // text rows (label, "from -> to  outcome").
    static QJsonArray selected(const ParameterDictionary &dict, const RestoreReport &report,
                               QList<QPair<QString, QString>> *rows);
    // verified / written / notWritten / mismatch / unconfirmed key lists (not for dry runs).
    static void insertOutcomes(const ParameterDictionary &dict, const RestoreReport &report, QJsonObject *json);
    // After a failure: "Written: ...", "Not written: ...", "Unknown (read them again): ...".
    static QStringList incomplete(const ParameterDictionary &dict, const RestoreReport &report);

private:
    static QString outcome(const RestoreReport &report, int index, QJsonObject *o);
};

} // namespace dd

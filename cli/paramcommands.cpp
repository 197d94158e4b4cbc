#include "cli/paramcommands.h"

#include "cli/clidescribe.h"
#include "cli/clijournal.h"
#include "cli/clivalues.h"
#include "core/protocol/familytraits.h"

#include "core/drive/drive.h"
#include "core/params/parameterdictionary.h"
#include "core/report/verificationjournal.h"

namespace dd {

// --- get --------------------------------------------------------------------------------

bool GetCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, -1, tr("one or more parameters, e.g. get PA12 P4 speed-gain"), error))
        return false;
    if (Error e = context()->dictionary->resolveList(inv.positionals, &m_indices)) {
        *error = e.message;
        return false;
    }
    return true;
}

void GetCommand::start()
{
    const ParameterDictionary &dict = *context()->dictionary;
    QList<int> readable;
    for (int i : std::as_const(m_indices)) {
        const ParameterInfo *p = dict.byIndex(i);
        if (p && p->isReadable())
            readable << i;
    }
    auto report = [this, &dict](const QMap<int, qint64> &values) {
        QJsonArray list;
        QList<QPair<QString, QString>> rows;
        for (int i : std::as_const(m_indices)) {
            const ParameterInfo *p = dict.byIndex(i);
            const bool known = values.contains(i);
            list.append(CliDescribe::parameter(dict, i, known ? std::optional<qint64>(values.value(i)) : std::nullopt));
            QString value = known ? QString::number(values.value(i)) : tr("not readable (write-only)");
            if (known && p && !p->unit.isEmpty())
                value += QLatin1Char(' ') + p->unit;
            rows.append({dict.label(i), value});
        }
        succeed({{QStringLiteral("parameters"), list}}, CliDescribe::table(rows));
    };
    if (readable.isEmpty())
        return report({});
    onFinished(drive()->readParameters(readable), [this, report](DriveReply *r) {
        if (!r->ok())
            return fail(r->error());
        report(r->parameters());
    });
}

// --- set --------------------------------------------------------------------------------

bool SetCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, -1, tr("one or more PARAM=VALUE, e.g. set PA12=300"), error))
        return false;
    const ParameterDictionary &dict = *context()->dictionary;
    QList<int> seen;
    for (const QString &arg : inv.positionals) {
        const int eq = arg.indexOf(QLatin1Char('='));
        if (eq <= 0 || eq == arg.size() - 1) {
            *error = tr("set: write PARAM=VALUE, e.g. PA12=300 (got \"%1\").").arg(arg);
            return false;
        }
        int index = -1;
        if (Error e = dict.resolve(arg.left(eq).trimmed(), &index)) {
            *error = e.message;
            return false;
        }
        if (seen.contains(index)) {
            *error = tr("set: %1 is given twice.").arg(dict.label(index));
            return false;
        }
        seen << index;
        const auto value = CliValues::integer(arg.mid(eq + 1), std::numeric_limits<qint64>::min() / 2,
                                              std::numeric_limits<qint64>::max() / 2, dict.label(index), error);
        if (!value)
            return false;
        // Range and access: every value is checked before anything is sent.
        if (Error e = dict.validateWrite(index, *value)) {
            *error = e.message;
            return false;
        }
        m_writes.append({index, *value});
    }
    return true;
}

void SetCommand::start()
{
    const ParameterDictionary &dict = *context()->dictionary;
    onFinished(drive()->writeParameters(m_writes), [this, &dict](DriveReply *r) {
        QJsonArray list;
        QList<QPair<QString, QString>> rows;
        bool allGood = r->ok();
        for (const ParameterWrite &w : std::as_const(m_writes)) {
            const ParameterWriteResult *res = nullptr;
            for (const ParameterWriteResult &x : r->writeResults())
                if (x.index == w.index)
                    res = &x;
            QJsonObject o = CliDescribe::parameter(dict, w.index, std::nullopt);
            o.insert(QStringLiteral("requested"), double(w.value));
            QString state;
            if (!res) {
                state = tr("not written");
                o.insert(QStringLiteral("result"), QStringLiteral("not-attempted"));
                allGood = false;
            } else {
                o.insert(QStringLiteral("written"), res->written);
                o.insert(QStringLiteral("verified"), res->verified);
                if (res->readable && res->written)
                    o.insert(QStringLiteral("readBack"), double(res->readBack));
                if (!res->error.isEmpty())
                    o.insert(QStringLiteral("message"), res->error);
                if (!res->written) {
                    state = tr("NOT WRITTEN: %1").arg(res->error);
                    o.insert(QStringLiteral("result"), QStringLiteral("failed"));
                    allGood = false;
                } else if (res->verified) {
                    state = tr("verified");
                    o.insert(QStringLiteral("result"), QStringLiteral("verified"));
                } else if (!res->readable) {
                    state = tr("written (write-only: cannot be read back)");
                    o.insert(QStringLiteral("result"), QStringLiteral("written-only"));
                } else {
                    state = tr("MISMATCH: read back %1").arg(res->readBack);
                    o.insert(QStringLiteral("result"), QStringLiteral("mismatch"));
                    allGood = false;
                }
            }
            list.append(o);
            rows.append({dict.label(w.index), QStringLiteral("= %1  %2").arg(w.value).arg(state)});
        }
        const QJsonObject json{{QStringLiteral("parameters"), list}};
        CliJournal::verification(context(), VerificationJournal::fromWrites(r->writeResults(), dict));
        if (!allGood) {
            out()->line(CliDescribe::table(rows));
            Error e = r->error();
            if (!e)
                e = {ErrorCode::VerifyMismatch, tr("Not every value was verified.")};
            return fail(e, json);
        }
        if (familyTraits(context()->globals.connection.family).eeOperations)
            out()->note(tr("The values are in the drive's RAM; `ee set` stores them to EEPROM."));
        succeed(json, CliDescribe::table(rows));
    });
}

} // namespace dd

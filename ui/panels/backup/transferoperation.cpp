#include "ui/panels/backup/transferoperation.h"

#include "core/drive/drive.h"
#include "core/drive/drivereply.h"
#include "core/drive/parametertransfer.h"
#include "core/params/parameterdictionary.h"

namespace dd {

namespace {
using Start = std::function<void(ParameterTransfer &)>;

DriveHub::Operation transferOperation(Start start, std::shared_ptr<TransferOutcome> out)
{
    return [start, out](Drive &drive) -> DriveReply * {
        auto *reply = new DriveReply(&drive);
        auto *transfer = new ParameterTransfer(&drive, reply);
        out->dictionary = drive.dictionary();
        if (!out->dictionary) {
            // The bundled dictionaries live as long as the program: no ownership needed.
            out->dictionary = std::shared_ptr<const ParameterDictionary>(&ParameterDictionary::bundled(drive.family()),
                                                                         [](const ParameterDictionary *) {});
        }
        QObject::connect(transfer, &ParameterTransfer::progress, reply, &DriveReply::reportProgress);
        QObject::connect(transfer, &ParameterTransfer::finished, reply, [transfer, reply, out](const Error &error) {
            out->backup = transfer->backupFile();
            out->diff = transfer->diff();
            out->report = transfer->report();
            reply->finish(error);
        });
        start(*transfer);
        return reply;
    };
}
} // namespace

DriveHub::Operation TransferOperation::backup(std::shared_ptr<TransferOutcome> out)
{
    return transferOperation([](ParameterTransfer &t) { t.backup(); }, std::move(out));
}

DriveHub::Operation TransferOperation::compare(const BackupFile &file, std::shared_ptr<TransferOutcome> out)
{
    return transferOperation([file](ParameterTransfer &t) { t.compare(file); }, std::move(out));
}

DriveHub::Operation TransferOperation::restore(const BackupFile &file, const RestoreOptions &options,
                                               std::shared_ptr<TransferOutcome> out)
{
    return transferOperation([file, options](ParameterTransfer &t) { t.restore(file, options); }, std::move(out));
}

} // namespace dd

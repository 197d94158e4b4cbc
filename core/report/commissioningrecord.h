#pragma once

#include "core/report/driverecord.h"
#include "core/report/recordheader.h"

#include <QList>
#include <QLocale>

namespace dd {

// A commissioning record: the header and one DriveRecord per drive. RecordJson turns it into
// the versioned JSON file, RecordRenderer into the PDF (docs/record.md).
struct CommissioningRecord
{
    RecordHeader header;
    QList<DriveRecord> drives;
    QLocale locale; // the language it is written in
};

} // namespace dd

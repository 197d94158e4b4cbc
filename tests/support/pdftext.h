#pragma once

#include <QString>

namespace dd::test {

// The text of a PDF as poppler's pdftotext extracts it (-layout), pages first..last (1-based;
// 0: from the first / to the last). Empty, with *error set, when pdftotext is missing
// (packaging/install-deps.sh installs poppler-utils) or fails.
QString pdfText(const QString &path, int firstPage = 0, int lastPage = 0, QString *error = nullptr);
// A PDF's page count and page size in points, from pdfinfo ("612 x 792 pts (letter)").
QString pdfInfo(const QString &path, QString *error = nullptr);

} // namespace dd::test

// The replay of the fuzz targets when libFuzzer is not linked (gcc, or a build without
// DRIVEDESK_FUZZ): runs a target's LLVMFuzzerTestOneInput once on every file named on the
// command line or found (recursively) in a directory named there, so that the committed
// corpus - and every crash reproducer added to it - is a regression test in the ordinary test
// suite. All targets share one program, drivedesk_fuzz_replay (tests/fuzz/CMakeLists.txt
// renames each target's entry point and generates the table): `drivedesk_fuzz_replay
// fuzz_backupfile corpus/fuzz_backupfile ...`.
// Exit status: 0 when every input ran; 1 when an argument names nothing or no input was found;
// 2 when the first argument names no target. A failed invariant or a sanitizer report aborts
// the process.

#include <QByteArray>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QStringList>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "replaymain.h"

int replayFuzzInputs(int argc, char **argv, FuzzEntry entry)
{
    QStringList files;
    for (int i = 1; i < argc; ++i) {
        const QString arg = QString::fromLocal8Bit(argv[i]);
        const QFileInfo info(arg);
        if (info.isDir()) {
            QStringList found;
            QDirIterator it(arg, QDir::Files, QDirIterator::Subdirectories);
            while (it.hasNext())
                found.append(it.next());
            std::sort(found.begin(), found.end());
            files += found;
        } else if (info.isFile()) {
            files.append(arg);
        } else {
            std::fprintf(stderr, "replay: %s is neither a file nor a directory\n", argv[i]);
            return 1;
        }
    }
    if (files.isEmpty()) {
        std::fprintf(stderr, "replay: no inputs (give corpus files or directories)\n");
        return 1;
    }
    for (const QString &path : std::as_const(files)) {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly)) {
            std::fprintf(stderr, "replay: cannot read %s\n", qPrintable(path));
            return 1;
        }
        const QByteArray bytes = f.readAll();
        std::fprintf(stderr, "replay: %s (%lld bytes)\n", qPrintable(path), static_cast<long long>(bytes.size()));
        entry(reinterpret_cast<const uint8_t *>(bytes.constData()), static_cast<size_t>(bytes.size()));
    }
    std::printf("replay: %lld inputs ran\n", static_cast<long long>(files.size()));
    return 0;
}

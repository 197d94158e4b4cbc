# What keeps a build from cold inside CI's time (docs/performance.md, "CI time").
#
# Precompiled headers: every translation unit of the tree includes the same large Qt headers
# (a test file includes <QtTest>, which is the whole of QtCore), and parsing them was most of
# the compiler's work. Each layer library and each test program precompiles the Qt headers its
# sources use most, once; a source still includes what it uses (the precompiled header only
# saves the parsing), and DRIVEDESK_PCH=OFF builds without it to check that.
option(DRIVEDESK_PCH "Precompile the common Qt headers of each library and test program" ON)

# Unity builds: the sources of a library or test program are compiled eight at a time, as one
# translation unit each. What a file instantiates (Qt's containers and signals, std::function)
# is then compiled once per eight files instead of once per file: about a third less compiler
# time (docs/performance.md, "CI time"). A file's helpers live in an anonymous namespace, so
# within one library or test program their names must differ between files (a clash is a
# compile error here, never a silent merge); DRIVEDESK_UNITY=OFF builds file by file.
option(DRIVEDESK_UNITY "Compile the sources of each target eight at a time (unity build)" ON)
if(DRIVEDESK_UNITY)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
endif()

set(drivedesk_pch_core
    <QtCore/QObject> <QtCore/QString> <QtCore/QStringList> <QtCore/QList> <QtCore/QByteArray>
    <QtCore/QHash> <QtCore/QMap> <QtCore/QSet> <QtCore/QVariant> <QtCore/QJsonObject>
    <QtCore/QJsonArray> <QtCore/QJsonDocument> <QtCore/QTimer> <QtCore/QPointer>
    <QtCore/QDateTime> <QtCore/QCoreApplication> <QtCore/QElapsedTimer> <QtCore/QFile>
    <QtCore/QDir> <QtCore/QFileInfo> <QtCore/QLocale> <QtCore/QLoggingCategory>
    <algorithm> <functional> <memory> <optional> <vector>)
set(drivedesk_pch_widgets
    <QtWidgets/QWidget> <QtWidgets/QApplication> <QtWidgets/QLabel> <QtWidgets/QPushButton>
    <QtWidgets/QBoxLayout> <QtWidgets/QComboBox> <QtWidgets/QTableWidget>
    <QtWidgets/QHeaderView> <QtWidgets/QMenu> <QtWidgets/QMessageBox> <QtWidgets/QLineEdit>
    <QtWidgets/QCheckBox> <QtWidgets/QSpinBox> <QtWidgets/QGroupBox> <QtWidgets/QDialog>)

#   drivedesk_precompile(<target> [WIDGETS] [TEST])
# WIDGETS: the target sees Qt Widgets; TEST: a test program (adds <QtTest> and
# tests/support/testmain.h, which every test file of a test program needs first).
function(drivedesk_precompile target)
  if(NOT DRIVEDESK_PCH)
    return()
  endif()
  cmake_parse_arguments(arg "WIDGETS;TEST" "" "" ${ARGN})
  set(headers ${drivedesk_pch_core})
  if(arg_WIDGETS)
    list(APPEND headers ${drivedesk_pch_widgets})
  endif()
  if(arg_TEST)
    list(APPEND headers <QtTest/QtTest> "${PROJECT_SOURCE_DIR}/tests/support/testmain.h")
  endif()
  list(TRANSFORM headers PREPEND "$<$<COMPILE_LANGUAGE:CXX>:")
  list(TRANSFORM headers APPEND ">")
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()

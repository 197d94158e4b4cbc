#pragma once

#include <QAction>

namespace dd {

class MainWindow;

// File → Load dictionary…: loads a parameter dictionary for the selected drive (its
// Parameters tab is shown and asks for the file; ParametersPanel::chooseDictionary()).
// Disabled while no drive is selected.
class LoadDictionaryAction : public QAction
{
    Q_OBJECT
public:
    explicit LoadDictionaryAction(MainWindow *window);

private:
    void retranslate();
    void open();

    MainWindow *m_window;
};

} // namespace dd

#include "ui/common/livetext.h"

#include <QEvent>
#include <QLabel>

namespace dd {

namespace {
const QString ObjectName = QStringLiteral("ddLiveText");
}

LiveText::LiveText(QLabel *label, std::function<QString()> make)
    : QObject(label)
    , m_label(label)
    , m_make(std::move(make))
{
    setObjectName(ObjectName);
}

void LiveText::set(QLabel *label, std::function<QString()> make)
{
    clear(label);
    auto *live = new LiveText(label, std::move(make));
    label->setText(live->m_make());
}

void LiveText::clear(QLabel *label)
{
    delete label->findChild<LiveText *>(ObjectName, Qt::FindDirectChildrenOnly);
}

std::function<QString()> LiveText::maker(const QLabel *label)
{
    const auto *live = label->findChild<LiveText *>(ObjectName, Qt::FindDirectChildrenOnly);
    return live ? live->m_make : std::function<QString()>();
}

bool LiveText::event(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_make)
        m_label->setText(m_make());
    return QObject::event(event);
}

} // namespace dd

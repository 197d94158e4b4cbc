#pragma once

#include <QJsonObject>

#include <functional>

namespace dd::test {

// A change to a JSON document (a dictionary or a backup file) made by a test.
using JsonMutation = std::function<void(QJsonObject &)>;

// Applies `f` to the object at parameters[i] of the document.
JsonMutation onParameterEntry(int i, std::function<void(QJsonObject &)> f);

} // namespace dd::test

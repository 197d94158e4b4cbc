#include "tests/support/jsonmutation.h"

#include <QJsonArray>

namespace dd::test {

JsonMutation onParameterEntry(int i, std::function<void(QJsonObject &)> f)
{
    return [i, f](QJsonObject &root) {
        QJsonArray a = root.value("parameters").toArray();
        QJsonObject e = a.at(i).toObject();
        f(e);
        a[i] = e;
        root["parameters"] = a;
    };
}

} // namespace dd::test

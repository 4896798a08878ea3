#pragma once
// Shared by the simcore tests: a parameter set from a list, failing loudly on a bad key.

#include <QtGlobal>

#include <initializer_list>
#include <utility>

#include "simcore/params.h"

namespace testsupport {

inline simcore::ParameterSet params(simcore::SceneKind kind,
                                    std::initializer_list<std::pair<const char*, double>> values) {
    simcore::ParameterSet p(kind);
    for (auto [key, value] : values) {
        const auto error = p.set(key, value);
        if (error) qFatal("%s", error->c_str());
    }
    return p;
}

}  // namespace testsupport

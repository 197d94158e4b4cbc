#pragma once

#include "core/params/parameterset.h"

namespace dd {

class ParameterDictionary;

// The dictionary's default values as a parameter set, and the part of a set that differs
// from them ("changed from default only": backup --changed-only, the GUI's save offer).
class DefaultValues
{
public:
    // Every parameter with a default value.
    static ParameterSet of(const ParameterDictionary &dictionary);
    // The writable settings of `values` that differ from their default, or that have no
    // default (they cannot be known unchanged). Read-only values (firmware, status) are
    // information, not settings: left out.
    static ParameterSet changedOnly(const ParameterDictionary &dictionary, const ParameterSet &values);
    // `values` completed with the defaults of the parameters it leaves out: what a
    // changed-only file means for the parameters it does not list.
    static ParameterSet completed(const ParameterDictionary &dictionary, const ParameterSet &values);
};

} // namespace dd

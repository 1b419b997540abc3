#include "CoreDefaults.hpp"

#include <stdexcept>

namespace unimap::payload {

void CoreDefaults::AddTo(ParameterSet* set) const {
  // The reasons in CoreParameters::Keys() order.
  const std::string* const reasons[] = {&why_n,       &why_m,          &why_i,        &why_sigma_a,
                                        &why_sigma_g, &why_resolution, &why_max_range};
  const auto& keys = CoreParameters::Keys();
  ParameterSet core;
  values.AddTo(&core);
  for (ParameterSpec spec : core.specs()) {
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (spec.key == keys[k] && !reasons[k]->empty()) spec.description += "; " + *reasons[k];
    }
    set->Add(std::move(spec));
  }
}

}  // namespace unimap::payload

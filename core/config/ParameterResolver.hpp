#pragma once
// Internal to libunimap_config (exported for its tests only, not installed):
// applies a platform file's overrides to a plugin's parameter set.
#include <string>
#include <vector>

#include "PlatformFile.hpp"
#include "unimap/Export.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"
#include "unimap/Platform.hpp"

namespace unimap {

// Effective parameters: the plugin's defaults overridden by a file.
struct ResolvedParameters {
  ParameterMap parameters;                    // every key of the set, coerced to its spec's type
  std::vector<EffectiveParameter> effective;  // the same values in spec order, with provenance
};

// Validates overrides against one plugin's ParameterSet.
class UNIMAP_CORE_API ParameterResolver {
 public:
  // The set must outlive the resolver.
  explicit ParameterResolver(const ParameterSet& set);

  // Defaults overridden by file.overrides(), each coerced with
  // ParameterSet::Coerce. Throws ConfigError(file, line, key, reason) for an
  // unknown key (suggesting the closest known key within edit distance 3, or
  // listing the keys below a group name), a wrong type, a value out of range
  // or a list of the wrong length.
  ResolvedParameters Resolve(const PlatformFile& file) const;

  // The known key closest to key by edit distance, or "" when none is within
  // max_distance edits.
  std::string ClosestKey(const std::string& key, std::size_t max_distance = 3) const;

 private:
  const ParameterSet& set_;
};

// Levenshtein distance (insertions, deletions, substitutions) between a and b.
UNIMAP_CORE_API std::size_t EditDistance(const std::string& a, const std::string& b);

}  // namespace unimap

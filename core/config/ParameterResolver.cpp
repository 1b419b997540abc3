#include "ParameterResolver.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

// An override after coercion to its spec's type.
struct CoercedOverride {
  ParameterValue value;  // of the spec's type
  int line = 0;          // where the file sets it
};

// True when text starts with prefix.
bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.size() >= prefix.size() && text.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

std::size_t EditDistance(const std::string& a, const std::string& b) {
  // Wagner-Fischer dynamic programme, one row at a time:
  //   d[i][j] = min(d[i-1][j] + 1, d[i][j-1] + 1, d[i-1][j-1] + (a[i-1] != b[j-1])).
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];  // d[i-1][j-1]
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];  // d[i-1][j]
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({above + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

ParameterResolver::ParameterResolver(const ParameterSet& set) : set_(set) {}

std::string ParameterResolver::ClosestKey(const std::string& key, std::size_t max_distance) const {
  std::string best;
  std::size_t best_distance = max_distance + 1;
  for (const ParameterSpec& spec : set_.specs()) {
    const std::size_t distance = EditDistance(key, spec.key);
    if (distance < best_distance) {  // strict: the first of equally close keys wins
      best = spec.key;
      best_distance = distance;
    }
  }
  return best;
}

ResolvedParameters ParameterResolver::Resolve(const PlatformFile& file) const {
  std::map<std::string, CoercedOverride> coerced;
  for (const ParameterOverride& entry : file.overrides()) {
    if (set_.Find(entry.key) == nullptr) {
      // Why the key is unknown, in the most helpful words available.
      std::vector<std::string> below;  // known keys inside a group of that name
      std::string value_prefix;        // a known key written as if it were a group
      for (const ParameterSpec& spec : set_.specs()) {
        if (StartsWith(spec.key, entry.key + ".")) below.push_back(spec.key);
        if (StartsWith(entry.key, spec.key + ".")) value_prefix = spec.key;
      }
      std::string reason = "unknown parameter";
      if (!below.empty()) {
        reason = "is a group, not a parameter; its parameters are ";
        for (std::size_t i = 0; i < below.size(); ++i) reason += (i > 0 ? ", " : "") + below[i];
      } else if (!value_prefix.empty()) {
        reason += "; '" + value_prefix + "' takes a value, not nested keys";
      } else if (const std::string closest = ClosestKey(entry.key); !closest.empty()) {
        reason += " (did you mean '" + closest + "'?)";
      }
      throw ConfigError(file.file(), entry.line, entry.key, reason);
    }
    CoercedOverride accepted;
    accepted.line = entry.line;
    std::string why;
    if (!set_.Coerce(entry.key, entry.value, &accepted.value, &why)) {
      throw ConfigError(file.file(), entry.line, entry.key, why);
    }
    coerced[entry.key] = std::move(accepted);
  }

  ResolvedParameters resolved;
  resolved.effective.reserve(set_.specs().size());
  for (const ParameterSpec& spec : set_.specs()) {
    EffectiveParameter effective;
    effective.spec = spec;
    const auto found = coerced.find(spec.key);
    if (found == coerced.end()) {
      effective.value = spec.default_value;
      effective.source = ParameterSource::kPluginDefault;
    } else {
      effective.value = found->second.value;
      effective.source = ParameterSource::kPlatformFile;
      effective.line = found->second.line;
    }
    resolved.parameters.Set(spec.key, effective.value);
    resolved.effective.push_back(std::move(effective));
  }
  return resolved;
}

}  // namespace unimap

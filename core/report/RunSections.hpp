#pragma once
// run.json and metrics.json as the report's tables, read generically: a
// key added to either file later shows up with a readable name and unit
// (MetricLabels) without code changes.
#include <string>

#include <nlohmann/json.hpp>

namespace unimap::report {

// A JSON value as displayed: integers with thousands separators, other
// numbers with 4 significant digits (no exponent from 1000 up), arrays of
// numbers as "a / b / c", booleans as yes / no, null as n/a.
std::string DisplayValue(const nlohmann::ordered_json& value);

// The report's tables from run.json and metrics.json (either may be an
// empty object):
//   "cards":      headline figures [{label, value, unit, key}] (those present
//                 of: payload, motion, real-time factor, data duration, peak
//                 memory, submaps, loop closures, ATE, map error);
//   "sections":   [{title, key, rows: [{label, value, unit, key}]}]: run.json's
//                 top-level values ("Run"), then one per nested object
//                 (deeper objects flattened to dotted keys);
//   "parameters": [{key, symbol, value, source, meaning}] from run.json's
//                 "parameters" object;
//   "messages":   [{source, text}]: every string array named "messages";
//   "metrics":    [{label, value, unit, key, meaning}] for metrics.json.
nlohmann::ordered_json RunSections(const nlohmann::ordered_json& run, const nlohmann::ordered_json& metrics);

}  // namespace unimap::report

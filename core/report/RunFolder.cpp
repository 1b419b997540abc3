#include "report/RunFolder.hpp"

#include <cctype>
#include <fstream>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap::report {
namespace {

namespace fs = std::filesystem;

bool IsFile(const fs::path& file) {
  std::error_code ec;
  return fs::is_regular_file(file, ec);
}

// The JSON object in file; an empty object when the file does not exist.
nlohmann::ordered_json ReadJsonObject(const fs::path& file) {
  if (!IsFile(file)) return nlohmann::ordered_json::object();
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::ordered_json json;
  try {
    json = nlohmann::ordered_json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not valid JSON (" + e.what() + ")");
  }
  if (!json.is_object()) throw InputError(file.string() + ": expected a JSON object");
  return json;
}

// The named file (which must exist), else the first candidate that exists, else empty.
fs::path Pick(const fs::path& named, const char* role, const std::vector<fs::path>& candidates) {
  if (!named.empty()) {
    if (!IsFile(named)) throw InputError(std::string(role) + " " + named.string() + ": no such file");
    return named;
  }
  for (const fs::path& candidate : candidates) {
    if (!candidate.empty() && IsFile(candidate)) return candidate;
  }
  return {};
}

// run.json's string at object.key, or "".
std::string StringAt(const nlohmann::ordered_json& run, const char* object, const char* key) {
  const nlohmann::ordered_json* node = &run;
  if (object != nullptr) {
    const auto it = run.find(object);
    if (it == run.end() || !it->is_object()) return "";
    node = &*it;
  }
  const auto it = node->find(key);
  return it != node->end() && it->is_string() ? it->get<std::string>() : "";
}

bool IsMapExtension(const fs::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".ply" || ext == ".pcd";
}

}  // namespace

RunFolder ResolveRunFolder(const ReportOptions& options) {
  std::string reason;
  if (!options.IsValid(&reason)) throw InputError("report options: " + reason);
  std::error_code ec;
  if (!fs::is_directory(options.folder, ec))
    throw InputError("run folder " + options.folder.string() + ": no such folder");
  RunFolder f;
  f.folder = options.folder;
  f.run = ReadJsonObject(f.folder / "run.json");
  f.metrics = ReadJsonObject(f.folder / "metrics.json");
  f.estimate_file = Pick(options.estimate_file, "estimate", {f.folder / "trajectory.tum"});
  f.odometry_file = Pick(options.odometry_file, "odometry", {f.folder / "trajectory_odometry.tum"});
  if (!f.odometry_file.empty() && !f.estimate_file.empty() && fs::equivalent(f.odometry_file, f.estimate_file, ec)) {
    f.odometry_file.clear();  // e.g. unimap evaluate --estimate RUN_DIR/trajectory_odometry.tum
  }
  const std::string dataset = StringAt(f.run, nullptr, "dataset");
  const fs::path dataset_truth = dataset.empty() ? fs::path() : fs::path(dataset) / "groundtruth.tum";
  // A run of a recording read directly keeps its ground truth in the folder.
  f.truth_file = Pick(options.truth_file, "truth", {dataset_truth, f.folder / "groundtruth.tum"});
  fs::path prior_map = StringAt(f.run, "localize", "map");
  if (!IsMapExtension(prior_map)) prior_map.clear();
  f.map_file = Pick(options.map_file, "map", {f.folder / "map.ply", f.folder / "map.pcd", prior_map});
  f.loops_file = Pick({}, "loop closures", {f.folder / "loop_closures.csv"});

  if (f.estimate_file.empty() && f.map_file.empty()) {
    throw InputError("run folder " + f.folder.string() +
                     ": nothing to report (no trajectory.tum, no map.ply or map.pcd)");
  }
  if (f.truth_file.empty()) {
    f.notes.push_back(dataset.empty() ? "No ground truth: run.json names no dataset and none was given."
                                      : "No ground truth: " + dataset_truth.string() + " does not exist.");
  }
  if (f.map_file.empty()) f.notes.push_back("No map: the folder holds no map.ply or map.pcd.");
  if (f.estimate_file.empty()) f.notes.push_back("No trajectory: the folder holds no trajectory.tum.");
  return f;
}

}  // namespace unimap::report

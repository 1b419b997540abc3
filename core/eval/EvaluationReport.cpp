#include "eval/EvaluationReport.hpp"

#include <system_error>

#include "eval/AtomicFile.hpp"
#include "eval/MetricsJson.hpp"
#include "eval/TrajectoryFigures.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {

std::vector<std::filesystem::path> WriteEvaluationReport(const TrajectoryEvaluation& evaluation,
                                                         const std::filesystem::path& out_dir,
                                                         const ReportExtras& extras) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw Error("cannot create output folder " + out_dir.string() + ": " + ec.message());
  std::vector<std::filesystem::path> written;
  const auto write = [&](const std::string& name, const std::string& bytes) {
    const std::filesystem::path file = out_dir / name;
    WriteFileAtomically(file, bytes);
    written.push_back(file);
  };
  write("metrics.json", MetricsToJson(evaluation.metrics, extras.metrics));
  const std::vector<Figure> figures = RenderTrajectoryFigures(evaluation);
  for (const Figure& figure : figures) write(figure.file_name, figure.png);
  return written;
}

}  // namespace unimap::eval

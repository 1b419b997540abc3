#include "DatasetChecks.hpp"

#include <iostream>

#include "unimap/Errors.hpp"

namespace unimap::cli {

void CheckDatasetForPlatform(io::DatasetReader& reader, const std::string& data_dir, const PayloadPlugin& plugin,
                             bool force_payload) {
  const std::string& recorded = reader.metadata().payload;
  if (!recorded.empty() && recorded != plugin.Name()) {
    const std::string mismatch = data_dir + ": the dataset was recorded for payload '" + recorded +
                                 "', the platform's plugin is '" + plugin.Name() + "'";
    if (!force_payload) {
      throw InputError(mismatch +
                       ": its scans and encoder would be read with the wrong sensor model (--force-payload runs it "
                       "anyway)");
    }
    std::cerr << "warning: " << mismatch << " (--force-payload)\n";
  }
  if (!reader.has_scans()) {
    throw InputError(data_dir + ": the dataset holds no scan (scans.bin is absent or has no record): nothing to map");
  }
  if (plugin.UsesEncoder() && !reader.has_encoder()) {
    throw InputError(data_dir + ": payload '" + plugin.Name() +
                     "' needs motor encoder samples (encoder.csv), the dataset has none");
  }
}

}  // namespace unimap::cli

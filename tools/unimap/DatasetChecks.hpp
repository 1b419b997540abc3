#pragma once
// What `unimap run` and `unimap localize` check of a dataset before any work.
#include <string>

#include "io/DatasetReader.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap::cli {

// Throws InputError naming the dataset folder when it cannot give the
// platform's payload anything to map: it was recorded for another payload
// than the plugin's (metadata.yaml `payload`; with force_payload only a
// warning on stderr), it holds no scan (scans.bin absent or without a
// record), or the payload needs a motor encoder and it has no encoder sample.
void CheckDatasetForPlatform(io::DatasetReader& reader, const std::string& data_dir, const PayloadPlugin& plugin,
                             bool force_payload);

}  // namespace unimap::cli

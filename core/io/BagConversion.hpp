#pragma once
// Internal to unimap_io: the writing loop ConvertRosbag and ConvertRos2Bag
// share (a bag reader's messages into a dataset folder).
#include <string>

#include "io/BagReader.hpp"
#include "io/DatasetConversion.hpp"

namespace unimap::io {

// Notes the topic choice, then writes every message of the reader into
// options.output (one scan stream: the cloud topic if selected, else the
// laser topic; metadata source `source`; the payload options.payload or one
// the streams imply), stopping early when options.stop is set. Adds the
// reader's skips (stats(), read after the last message) to the report.
// Throws what Next() throws, and InputError from the dataset writer.
ConversionReport WriteBagDataset(const ConversionOptions& options, const std::string& source, BagReader& reader);

}  // namespace unimap::io

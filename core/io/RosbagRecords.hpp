#pragma once
// Internal to unimap_io: a structural check of a ROS 1 bag (format 2.0)
// before librosbag_storage opens it. librosbag trusts the lengths it reads
// and allocates them (a corrupt length: a 4 GiB malloc, found by fuzzing).
#include <filesystem>

namespace unimap::io {

// Walks the top-level records of the bag: "#ROSBAG V2.0\n", then per record
// a u32 header length, the header (fields: u32 length, "name=value"), a u32
// data length and the data; and the records inside each chunk, uncompressed
// (none, bz2, lz4) to the size it announces. Throws InputError "<bag>:
// record at byte B: <reason>" when a length runs past the end of the file,
// its chunk or its header (a connection record's data is a header too), a
// field has no '=', a chunk announces more than 1 GiB uncompressed (or
// another size than it uncompresses to), an index data entry names an
// offset that is not a record of the chunk before it, or the bag header's
// index_pos or a chunk info's chunk_pos is not the start of a record walked
// (of a chunk for chunk_pos): librosbag reads a record at each of these
// places with the lengths it finds there unchecked.
void CheckRosbagRecords(const std::filesystem::path& bag);

}  // namespace unimap::io

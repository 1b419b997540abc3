#pragma once
// Writes an occupancy octree as an OctoMap binary file (.bt: what octovis,
// octomap_server and octomap::OcTree(filename) read).
#include <filesystem>

namespace octomap {
class OcTree;
}

namespace unimap::map {

// Writes tree to file in OctoMap's binary format (OcTree::writeBinaryConst:
// header "# Octomap OcTree binary file", id OcTree, resolution, then two bits
// per child, occupied / free). The format keeps each node's maximum-
// likelihood state only, not its log-odds: a leaf reads back as occupied
// exactly when tree.isNodeOccupied(leaf) held, with the tree's clamping
// log-odds as its value. The tree is not modified (no pruning; octomap
// prunes on reading). Atomic: "<file>.partial" is written and renamed into
// place (io::PartialFile). Throws InputError naming the file, leaving no
// <file> and no "<file>.partial", when it cannot be written.
void WriteOctomapBinary(const std::filesystem::path& file, const octomap::OcTree& tree);

}  // namespace unimap::map

#include "map/OctomapWriter.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <tuple>

#include <gtest/gtest.h>
#include <octomap/OcTree.h>
#include <unistd.h>

#include "unimap/Errors.hpp"

namespace unimap::map {
namespace {

// A fresh folder under the system temp folder, removed with its contents.
class Scratch {
 public:
  Scratch() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("unimap_map_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~Scratch() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

using Leaf = std::tuple<unsigned, unsigned, unsigned, unsigned>;  // key x, y, z, depth

// (key, depth) of every leaf in the given state, after expanding nothing:
// compared as sets so the order of iteration does not matter.
std::set<Leaf> Leaves(const octomap::OcTree& tree, bool occupied) {
  std::set<Leaf> leaves;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    if (tree.isNodeOccupied(*it) != occupied) continue;
    const octomap::OcTreeKey key = it.getKey();
    leaves.emplace(key[0], key[1], key[2], it.getDepth());
  }
  return leaves;
}

// A small deterministic tree: rays from the origin to random points on a
// 2 m x 2 m wall at x = 3 (occupied wall voxels, free space in front),
// pruned the way OctoMap prunes when it reads a file.
octomap::OcTree SmallTree(bool prune = true) {
  octomap::OcTree tree(0.1);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> side(-1.0, 1.0);
  octomap::Pointcloud cloud;
  for (int i = 0; i < 300; ++i) {
    cloud.push_back(3.0f, static_cast<float>(side(rng)), static_cast<float>(side(rng)));
  }
  tree.insertPointCloud(cloud, octomap::point3d(0.0f, 0.0f, 0.0f));
  if (prune) {
    tree.toMaxLikelihood();
    tree.prune();
  }
  return tree;
}

TEST(OctomapWriter, ReadsBackWithTheSameOccupiedAndFreeLeaves) {
  Scratch dir;
  const octomap::OcTree tree = SmallTree();
  const std::set<Leaf> occupied = Leaves(tree, true);
  const std::set<Leaf> free = Leaves(tree, false);
  ASSERT_GT(occupied.size(), 100u);
  ASSERT_GT(free.size(), 100u);
  const std::filesystem::path file = dir / "map.bt";
  WriteOctomapBinary(file, tree);
  EXPECT_FALSE(std::filesystem::exists(dir / "map.bt.partial"));

  const octomap::OcTree read(file.string());
  EXPECT_DOUBLE_EQ(read.getResolution(), 0.1);
  EXPECT_EQ(Leaves(read, true), occupied);
  EXPECT_EQ(Leaves(read, false), free);
}

TEST(OctomapWriter, UnprunedTreeKeepsEveryVoxelsState) {
  Scratch dir;
  const octomap::OcTree tree = SmallTree(false);
  WriteOctomapBinary(dir / "map.bt", tree);
  const octomap::OcTree read((dir / "map.bt").string());
  std::size_t checked = 0;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it, ++checked) {
    const octomap::OcTreeNode* node = read.search(it.getKey(), it.getDepth());
    ASSERT_NE(node, nullptr) << "leaf " << checked;
    ASSERT_EQ(read.isNodeOccupied(node), tree.isNodeOccupied(*it)) << "leaf " << checked;
  }
  EXPECT_GT(checked, 1000u);
}

TEST(OctomapWriter, FileStartsWithOctomapsBinaryHeader) {
  Scratch dir;
  WriteOctomapBinary(dir / "map.bt", SmallTree());
  std::ifstream in(dir / "map.bt", std::ios::binary);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "# Octomap OcTree binary file");
}

TEST(OctomapWriter, EmptyTreeReadsBackEmpty) {
  Scratch dir;
  WriteOctomapBinary(dir / "empty.bt", octomap::OcTree(0.2));
  const octomap::OcTree read((dir / "empty.bt").string());
  EXPECT_EQ(read.size(), 0u);
  EXPECT_DOUBLE_EQ(read.getResolution(), 0.2);
}

TEST(OctomapWriter, UnwritableFolderIsAnInputErrorNamingTheFile) {
  Scratch dir;
  const std::filesystem::path file = dir / "missing" / "map.bt";
  try {
    WriteOctomapBinary(file, SmallTree());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace unimap::map

#include "io/PcdPointLoader.hpp"

#include "unimap/Errors.hpp"

#if UNIMAP_WITH_PCL
#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#endif

namespace unimap::io {

#if UNIMAP_WITH_PCL

bool PcdSupported() { return true; }

void LoadPcdXyzi(const std::filesystem::path& file, std::vector<Eigen::Vector4f>* xyzi) {
  const std::string name = file.string();
  // Read the header first: PCL fills missing fields with zeros silently, but
  // a cloud without x/y/z is not a LiDAR scan.
  pcl::PCDReader reader;
  pcl::PCLPointCloud2 header;
  if (reader.readHeader(name, header) != 0) throw InputError(name + ": not a readable PCD file");
  bool has_x = false, has_y = false, has_z = false;
  for (const pcl::PCLPointField& field : header.fields) {
    has_x = has_x || field.name == "x";
    has_y = has_y || field.name == "y";
    has_z = has_z || field.name == "z";
  }
  if (!(has_x && has_y && has_z)) throw InputError(name + ": PCD file has no x y z fields");
  pcl::PointCloud<pcl::PointXYZI> cloud;
  if (reader.read(name, cloud) != 0) throw InputError(name + ": PCD data cannot be read (damaged or truncated)");
  xyzi->clear();
  xyzi->reserve(cloud.size());
  for (const pcl::PointXYZI& p : cloud.points) xyzi->emplace_back(p.x, p.y, p.z, p.intensity);
}

#else

bool PcdSupported() { return false; }

void LoadPcdXyzi(const std::filesystem::path& file, std::vector<Eigen::Vector4f>* /*xyzi*/) {
  throw InputError(file.string() + ": this build of unimap has no PCD support (PCL was not found at configure time)");
}

#endif

}  // namespace unimap::io

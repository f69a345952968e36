#include "api/result_xdmf.hpp"

#include "api/hdf5_objects.hpp"
#include "api/result_layout.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace slipfront::api {

namespace {

std::vector<hsize_t> shape_of(hid_t file, const std::string& path) {
  hdf5::Handle dataset = hdf5::open_dataset(file, path);
  hdf5::Handle space(hdf5::check_id(H5Dget_space(dataset.get()), "dataspace of " + path));
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) throw std::runtime_error("cannot read the rank of " + path);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  hdf5::check(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), "dims of " + path);
  return dims;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

std::string data_item(const std::string& dims, const char* number_type, int precision,
                      const std::string& h5, const std::string& path) {
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + number_type + "\" Precision=\"" +
         std::to_string(precision) + "\" Format=\"HDF\">" + h5 + ":" + path + "</DataItem>";
}

} // namespace

std::string result_xdmf(const std::string& h5_path, const std::string& h5_reference) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hdf5::Handle file(hdf5::check_id(H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                                   "opening result file " + h5_path));
  const std::string x1_path = layout::path(layout::interface_group, layout::x1);
  const std::string time_path = layout::path(layout::interface_group, layout::time);
  const auto x1 = shape_of(file.get(), x1_path);
  const auto time = shape_of(file.get(), time_path);
  if (x1.size() != 1 || time.size() != 1)
    throw std::runtime_error(h5_path + ": " + x1_path + " and " + time_path + " must be 1-D");
  const std::string n_nodes = std::to_string(x1[0]);
  const std::string n_samples = std::to_string(time[0]);
  const std::string plane = n_samples + " " + n_nodes;
  const std::string h5 = xml_escape(h5_reference);

  std::string x;
  x += "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n";
  x += "<!-- slipfront result: the interface fields in the x1-t plane (docs/hdf5-layout.md).\n"
       "     X = x1 [m], Y = time [s]; every array is a dataset of " +
       h5 + " -->\n";
  x += "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n";
  x += "  <Domain>\n";
  x += "    <Grid Name=\"interface\" GridType=\"Uniform\">\n";
  x += "      <Topology TopologyType=\"2DRectMesh\" Dimensions=\"" + plane + "\"/>\n";
  x += "      <Geometry GeometryType=\"VXVY\">\n";
  x += "        " + data_item(n_nodes, "Float", 8, h5, x1_path) + "\n";
  x += "        " + data_item(n_samples, "Float", 8, h5, time_path) + "\n";
  x += "      </Geometry>\n";
  for (const auto& f : layout::all_fields) {
    const std::string path = layout::path(layout::interface_group, f.name);
    const auto dims = shape_of(file.get(), path);
    if (dims.size() != 2 || dims[0] != time[0] || dims[1] != x1[0])
      throw std::runtime_error(h5_path + ": " + path + " is not [n_samples, n_nodes]");
    x += std::string("      <Attribute Name=\"") + f.name +
         "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
    x += "        " + data_item(plane, f.xdmf_number_type, f.precision, h5, path) + "\n";
    x += "      </Attribute>\n";
  }
  x += "    </Grid>\n";
  x += "  </Domain>\n";
  x += "</Xdmf>\n";
  return x;
}

void write_result_xdmf(const std::string& h5_path, const std::string& xdmf_path) {
  const std::string text = result_xdmf(h5_path, std::filesystem::path(h5_path).filename().string());
  const std::string temp = xdmf_path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot create " + temp);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + temp);
  }
  if (std::rename(temp.c_str(), xdmf_path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw std::runtime_error("cannot rename " + temp + " to " + xdmf_path);
  }
}

} // namespace slipfront::api

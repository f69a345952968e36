#include "api/result_xdmf.hpp"

#include "api/hdf5_objects.hpp"
#include "api/result_layout.hpp"

#include <unistd.h>

#include <cstddef>
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

// Row `row` of the [n_samples, n_nodes] dataset at `path`, as an XDMF hyperslab of shape
// [1, n_nodes]: start (row, 0), stride (1, 1), count (1, n_nodes) over the whole dataset.
std::string row_item(std::size_t row, const std::string& n_nodes, const std::string& plane,
                     const layout::InterfaceField& f, const std::string& h5,
                     const std::string& path) {
  return "<DataItem ItemType=\"HyperSlab\" Dimensions=\"1 " + n_nodes +
         "\"><DataItem Dimensions=\"3 2\" Format=\"XML\">" + std::to_string(row) + " 0 1 1 1 " +
         n_nodes + "</DataItem>" + data_item(plane, f.xdmf_number_type, f.precision, h5, path) +
         "</DataItem>";
}

// A time as XML text with every digit a double holds (%.17g), so that the steps stay distinct.
std::string exact(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

} // namespace

std::string result_xdmf(const std::string& h5_path, const std::string& h5_reference) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hdf5::Handle file(hdf5::check_id(H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                                   "opening result file " + h5_path));
  const std::string x1_path = layout::path(layout::interface_group, layout::x1);
  const std::string time_path = layout::path(layout::interface_group, layout::time);
  const auto x1 = shape_of(file.get(), x1_path);
  std::vector<hsize_t> time_dims;
  hdf5::Handle group(
      hdf5::check_id(H5Gopen2(file.get(), layout::interface_group, H5P_DEFAULT),
                     std::string("opening ") + layout::interface_group + " of " + h5_path));
  const std::vector<double> times = hdf5::read_array(group.get(), layout::time, 1, time_dims);
  if (x1.size() != 1)
    throw std::runtime_error(h5_path + ": " + x1_path + " and " + time_path + " must be 1-D");
  const std::string n_nodes = std::to_string(x1[0]);
  const std::string n_samples = std::to_string(times.size());
  const std::string plane = n_samples + " " + n_nodes;
  const std::string h5 = xml_escape(h5_reference);
  for (const auto& f : layout::all_fields) {
    const std::string path = layout::path(layout::interface_group, f.name);
    const auto dims = shape_of(file.get(), path);
    if (dims.size() != 2 || dims[0] != times.size() || dims[1] != x1[0])
      throw std::runtime_error(h5_path + ": " + path + " is not [n_samples, n_nodes]");
  }
  const std::string x1_item = data_item(n_nodes, "Float", 8, h5, x1_path);

  std::string x;
  x += "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n";
  x += "<!-- slipfront result (docs/hdf5-layout.md): every array is a dataset of the HDF5 "
       "file the data items name, which must sit beside this file.\n"
       "     Grid \"interface\": a temporal collection, one line of nodes along x1 [m] per "
       "recorded time [s] (ParaView animates it).\n"
       "     Grid \"x1-t plane\": the same fields on one 2-D grid, X = x1 [m], Y = time [s]. "
       "-->\n";
  x += "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n";
  x += "  <Domain>\n";
  x += "    <Grid Name=\"interface\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < times.size(); ++k) {
    x += "      <Grid Name=\"step " + std::to_string(k) + "\" GridType=\"Uniform\">\n";
    x += "        <Time Value=\"" + exact(times[k]) + "\"/>\n";
    x += "        <Topology TopologyType=\"2DRectMesh\" Dimensions=\"1 " + n_nodes + "\"/>\n";
    x += "        <Geometry GeometryType=\"VXVY\">" + x1_item +
         "<DataItem Dimensions=\"1\" Format=\"XML\">0</DataItem></Geometry>\n";
    for (const auto& f : layout::all_fields) {
      const std::string path = layout::path(layout::interface_group, f.name);
      x += std::string("        <Attribute Name=\"") + f.name +
           "\" AttributeType=\"Scalar\" Center=\"Node\">" +
           row_item(k, n_nodes, plane, f, h5, path) + "</Attribute>\n";
    }
    x += "      </Grid>\n";
  }
  x += "    </Grid>\n";
  x += "    <Grid Name=\"x1-t plane\" GridType=\"Uniform\">\n";
  x += "      <Topology TopologyType=\"2DRectMesh\" Dimensions=\"" + plane + "\"/>\n";
  x += "      <Geometry GeometryType=\"VXVY\">\n";
  x += "        " + x1_item + "\n";
  x += "        " + data_item(n_samples, "Float", 8, h5, time_path) + "\n";
  x += "      </Geometry>\n";
  for (const auto& f : layout::all_fields) {
    const std::string path = layout::path(layout::interface_group, f.name);
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

// The panel's defaults (Plugin/ShrinkWrap.xml, which ParaView pushes to a new filter) against the
// filters' own, which come from the core's settings structs: a default changed in one place only
// would make the GUI and C++ or pvpython users run different filters.
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <functional>
#include <map>
#include <regex>

namespace
{
using Getter = std::function<std::vector<double>()>;

// command -> default_values of every vector property that sets something in the proxy `name`.
std::map<std::string, std::vector<double>> xmlDefaults(
  const std::string& xml, const std::string& name)
{
  std::map<std::string, std::vector<double>> defaults;
  const std::size_t begin = xml.find("<SourceProxy name=\"" + name + "\"");
  const std::size_t end = xml.find("</SourceProxy>", begin);
  if (begin == std::string::npos || end == std::string::npos)
  {
    return defaults;
  }
  const std::string proxy = xml.substr(begin, end - begin);
  const std::regex tag(R"x(<(Int|Double)VectorProperty\b[^>]*>)x");
  const std::regex command(R"x(command="(\w+)")x"), values(R"x(default_values="([^"]*)")x");
  for (auto it = std::sregex_iterator(proxy.begin(), proxy.end(), tag);
       it != std::sregex_iterator(); ++it)
  {
    const std::string text = it->str();
    std::smatch c, v;
    if (std::regex_search(text, c, command) && std::regex_search(text, v, values) &&
      c[1].str().rfind("Set", 0) == 0)
    {
      std::istringstream in(v[1].str());
      std::vector<double> numbers;
      for (double x; in >> x;)
      {
        numbers.push_back(x);
      }
      defaults[c[1].str()] = numbers;
    }
  }
  return defaults;
}

void compare(const std::string& proxy, const std::map<std::string, std::vector<double>>& xml,
  const std::map<std::string, Getter>& filter)
{
  SW_CHECK(xml.size() == filter.size(),
    proxy << ": the XML has " << xml.size() << " properties, the test knows " << filter.size());
  for (const auto& [command, get] : filter)
  {
    const auto found = xml.find(command);
    SW_CHECK(found != xml.end(), proxy << ": " << command << " is in the XML");
    if (found == xml.end())
    {
      continue;
    }
    const std::vector<double> value = get();
    bool same = value.size() == found->second.size();
    for (std::size_t k = 0; same && k < value.size(); ++k)
    {
      same = std::abs(value[k] - found->second[k]) <= 1e-12 * std::max(1.0, std::abs(value[k]));
    }
    SW_CHECK(same,
      proxy << ": " << command << " defaults to " << found->second[0] << " in the XML and "
            << value[0] << " in the filter");
  }
}
} // namespace

int TestPropertyDefaults(int argc, char* argv[])
{
  std::ifstream in(argc > 1 ? argv[1] : "");
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  SW_CHECK(!xml.empty(), "the plugin's XML is readable");

  vtkNew<vtkMeshSignedDistance> m;
  compare("MeshSignedDistance", xmlDefaults(xml, "MeshSignedDistance"),
    { { "SetInputGeometry", [&] { return std::vector<double>{ double(m->GetInputGeometry()) }; } },
      { "SetResolution", [&] { return std::vector<double>{ double(m->GetResolution()) }; } },
      { "SetCellSize", [&] { return std::vector<double>{ m->GetCellSize() }; } },
      { "SetComputeSign", [&] { return std::vector<double>{ double(m->GetComputeSign()) }; } },
      { "SetFieldPerBlock", [&] { return std::vector<double>{ double(m->GetFieldPerBlock()) }; } },
      { "SetBoxScale", [&] { return std::vector<double>{ m->GetBoxScale() }; } },
      { "SetOffsetFactor", [&] { return std::vector<double>{ m->GetOffsetFactor() }; } },
      { "SetSweepMethod", [&] { return std::vector<double>{ double(m->GetSweepMethod()) }; } },
      { "SetBandLayers", [&] { return std::vector<double>{ double(m->GetBandLayers()) }; } },
      { "SetUseExplicitGrid",
        [&] { return std::vector<double>{ double(m->GetUseExplicitGrid()) }; } },
      { "SetOutputBounds",
        [&] {
          const double* b = m->GetOutputBounds();
          return std::vector<double>(b, b + 6);
        } },
      { "SetOutputDimensions", [&] {
         const int* d = m->GetOutputDimensions();
         return std::vector<double>(d, d + 3);
       } } });

  vtkNew<vtkShrinkWrapFilter> w;
  auto one = [](double x) { return std::vector<double>{ x }; };
  compare("ShrinkWrap", xmlDefaults(xml, "ShrinkWrap"),
    { { "SetInputGeometry", [&] { return one(w->GetInputGeometry()); } },
      { "SetTimeStep", [&] { return one(w->GetTimeStep()); } },
      { "SetNumberOfSteps", [&] { return one(w->GetNumberOfSteps()); } },
      { "SetStartingShape", [&] { return one(w->GetStartingShape()); } },
      { "SetSubdivisionLevel", [&] { return one(w->GetSubdivisionLevel()); } },
      { "SetStartOffset", [&] { return one(w->GetStartOffset()); } },
      { "SetGapSize", [&] { return one(w->GetGapSize()); } },
      { "SetCloseHoles", [&] { return one(w->GetCloseHoles()); } },
      { "SetWrapPerBlock", [&] { return one(w->GetWrapPerBlock()); } },
      { "SetRemeshing", [&] { return one(w->GetRemeshing()); } },
      { "SetTargetEdgeLength", [&] { return one(w->GetTargetEdgeLength()); } },
      { "SetEdgeLengthRange",
        [&] {
          const double* r = w->GetEdgeLengthRange();
          return std::vector<double>(r, r + 2);
        } },
      { "SetTangentialRedistribution", [&] { return one(w->GetTangentialRedistribution()); } },
      { "SetC1", [&] { return one(w->GetC1()); } }, { "SetC2", [&] { return one(w->GetC2()); } },
      { "SetC", [&] { return one(w->GetC()); } }, { "SetD", [&] { return one(w->GetD()); } },
      { "SetOmegaAngle", [&] { return one(w->GetOmegaAngle()); } },
      { "SetOmegaVolume", [&] { return one(w->GetOmegaVolume()); } },
      { "SetDistanceWeighting", [&] { return one(w->GetDistanceWeighting()); } },
      { "SetRhoA", [&] { return one(w->GetRhoA()); } },
      { "SetEdgeFlips", [&] { return one(w->GetEdgeFlips()); } },
      { "SetEdgeCollapses", [&] { return one(w->GetEdgeCollapses()); } },
      { "SetCoverRims", [&] { return one(w->GetCoverRims()); } },
      { "SetFitFacets", [&] { return one(w->GetFitFacets()); } },
      { "SetCreaseAngle", [&] { return one(w->GetCreaseAngle()); } },
      { "SetFlipDihedralLimit", [&] { return one(w->GetFlipDihedralLimit()); } },
      { "SetInitialRelaxation", [&] { return one(w->GetInitialRelaxation()); } },
      { "SetAutomaticScaling", [&] { return one(w->GetAutomaticScaling()); } },
      { "SetSolverTolerance", [&] { return one(w->GetSolverTolerance()); } },
      { "SetResolution", [&] { return one(w->GetResolution()); } },
      { "SetCacheMemoryLimit", [&] { return one(w->GetCacheMemoryLimit()); } } });
  return testing::finish("TestPropertyDefaults");
}

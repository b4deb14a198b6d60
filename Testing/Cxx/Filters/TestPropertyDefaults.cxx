// The panel (Plugin/ShrinkWrap.xml, which ParaView pushes to a new filter, and whose documentation
// is the parameter reference) against the filters: every settable property's default equals the
// filter's own (which come from the core's settings structs), and its name, label, the unit its
// documentation states and the range its domain allows are those the filter describes and checks
// (DescribeProperties, CheckProperties). A default, a label or a
// unit changed in one place only would make the GUI and C++ or pvpython users read different
// filters. The Python name is the label without spaces and punctuation (TestUserTerms.py).
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include "PropertyBinding.h"

#include <algorithm>

#include <functional>
#include <map>
#include <regex>
#include <tuple>
#include <utility>

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

// Each settable property's XML element (name, label, command, documentation) of proxy `name`.
struct XmlProperty
{
  std::string name, label, command, documentation;
  double min = -shrinkwrap::convert::kNoLimit, max = shrinkwrap::convert::kNoLimit; // the domain's
};

// The smallest and the largest of the numbers in `text` ("0.1 1" -> 0.1, 1).
std::pair<double, double> extremes(const std::string& text)
{
  std::istringstream in(text);
  std::pair<double, double> range{ shrinkwrap::convert::kNoLimit, -shrinkwrap::convert::kNoLimit };
  for (double x; in >> x;)
  {
    range = { std::min(range.first, x), std::max(range.second, x) };
  }
  return range;
}

// The range the panel allows: a range domain's min and max (none: no limit), a switch 0 to 1, a
// choice its first to last entry.
void readRange(const std::string& body, XmlProperty& p)
{
  std::smatch m;
  if (std::regex_search(body, m, std::regex(R"x(<(Int|Double)RangeDomain\b([^>]*)>)x")))
  {
    const std::string tag = m[2].str();
    std::smatch v;
    if (std::regex_search(tag, v, std::regex(R"x(min="([^"]*)")x")))
    {
      p.min = extremes(v[1].str()).first;
    }
    if (std::regex_search(tag, v, std::regex(R"x(max="([^"]*)")x")))
    {
      p.max = extremes(v[1].str()).second;
    }
  }
  else if (body.find("<BooleanDomain") != std::string::npos)
  {
    p.min = 0;
    p.max = 1;
  }
  else if (body.find("<EnumerationDomain") != std::string::npos)
  {
    const std::regex entry(R"x(<Entry value="(-?\d+)")x");
    std::string values;
    for (auto it = std::sregex_iterator(body.begin(), body.end(), entry);
         it != std::sregex_iterator(); ++it)
    {
      values += (*it)[1].str() + " ";
    }
    std::tie(p.min, p.max) = extremes(values);
  }
}
std::vector<XmlProperty> xmlProperties(const std::string& xml, const std::string& name)
{
  std::vector<XmlProperty> found;
  const std::size_t begin = xml.find("<SourceProxy name=\"" + name + "\"");
  const std::size_t end = xml.find("</SourceProxy>", begin);
  const std::string proxy = begin == std::string::npos ? "" : xml.substr(begin, end - begin);
  const std::regex element(
    R"x(<(Int|Double)VectorProperty\b([^>]*)>([\s\S]*?)</(Int|Double)VectorProperty>)x");
  auto attribute = [](const std::string& tag, const char* key) {
    std::smatch m;
    return std::regex_search(tag, m, std::regex(std::string(key) + R"x(="([^"]*)")x")) ? m[1].str()
                                                                                       : "";
  };
  for (auto it = std::sregex_iterator(proxy.begin(), proxy.end(), element);
       it != std::sregex_iterator(); ++it)
  {
    const std::string tag = (*it)[2].str(), body = (*it)[3].str();
    XmlProperty p{ attribute(tag, "name"), attribute(tag, "label"), attribute(tag, "command"), "" };
    std::smatch doc;
    if (std::regex_search(body, doc, std::regex(R"x(<Documentation>([\s\S]*?)</Documentation>)x")))
    {
      p.documentation = std::regex_replace(doc[1].str(), std::regex(R"(\s+)"), " ");
    }
    readRange(body, p);
    if (p.command.rfind("Set", 0) == 0)
    {
      found.push_back(p);
    }
  }
  return found;
}

// Every settable XML property described by the filter alike: name (and Set<name>), label, unit.
void compareTerms(const std::string& proxy, const std::vector<XmlProperty>& xml,
  const std::vector<shrinkwrap::convert::PropertyInfo>& described)
{
  SW_CHECK(xml.size() == described.size(),
    proxy << ": the XML has " << xml.size() << " settable properties, the filter describes "
          << described.size());
  for (const XmlProperty& p : xml)
  {
    const auto d = std::find_if(described.begin(), described.end(),
      [&](const shrinkwrap::convert::PropertyInfo& info) { return p.name == info.name; });
    SW_CHECK(d != described.end(), proxy << ": " << p.name << " is described by the filter");
    if (d == described.end())
    {
      continue;
    }
    SW_CHECK(p.command == "Set" + p.name,
      proxy << ": " << p.name << " is set by Set" << p.name << ", not " << p.command);
    SW_CHECK(p.label == d->label,
      proxy << ": " << p.name << "'s label is '" << p.label << "', the filter's '" << d->label
            << "'");
    SW_CHECK(p.documentation.find(d->unit) != std::string::npos,
      proxy << ": " << p.name << "'s documentation states its unit, " << d->unit);
    const double lowest = p.min, highest = p.max; // what the filter refuses is what the panel does
    SW_CHECK(lowest == d->min && highest == d->max,
      proxy << ": " << p.name << "'s panel range is " << lowest << " to " << highest
            << ", the filter's " << d->min << " to " << d->max);
  }
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

  compareTerms("MeshSignedDistance", xmlProperties(xml, "MeshSignedDistance"),
    vtkMeshSignedDistance::DescribeProperties());
  compareTerms(
    "ShrinkWrap", xmlProperties(xml, "ShrinkWrap"), vtkShrinkWrapFilter::DescribeProperties());

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
      { "SetTimePerStep", [&] { return one(w->GetTimePerStep()); } },
      { "SetNumberOfSteps", [&] { return one(w->GetNumberOfSteps()); } },
      { "SetStartingShape", [&] { return one(w->GetStartingShape()); } },
      { "SetSubdivisionLevel", [&] { return one(w->GetSubdivisionLevel()); } },
      { "SetStartOffsetInCells", [&] { return one(w->GetStartOffsetInCells()); } },
      { "SetGapSize", [&] { return one(w->GetGapSize()); } },
      { "SetCloseHoles", [&] { return one(w->GetCloseHoles()); } },
      { "SetWrapPerBlock", [&] { return one(w->GetWrapPerBlock()); } },
      { "SetPassTargetArrays", [&] { return one(w->GetPassTargetArrays()); } },
      { "SetTimeMode", [&] { return one(w->GetTimeMode()); } },
      { "SetRemeshing", [&] { return one(w->GetRemeshing()); } },
      { "SetTargetEdgeLength", [&] { return one(w->GetTargetEdgeLength()); } },
      { "SetEdgeLengthRange",
        [&] {
          const double* r = w->GetEdgeLengthRange();
          return std::vector<double>(r, r + 2);
        } },
      { "SetTangentialRedistribution", [&] { return one(w->GetTangentialRedistribution()); } },
      { "SetSmoothing", [&] { return one(w->GetSmoothing()); } },
      { "SetSmoothingFalloff", [&] { return one(w->GetSmoothingFalloff()); } },
      { "SetAdvectionSpeed", [&] { return one(w->GetAdvectionSpeed()); } },
      { "SetConcavityPush", [&] { return one(w->GetConcavityPush()); } },
      { "SetAngleWeight", [&] { return one(w->GetAngleWeight()); } },
      { "SetVolumeWeight", [&] { return one(w->GetVolumeWeight()); } },
      { "SetDistanceWeighting", [&] { return one(w->GetDistanceWeighting()); } },
      { "SetDistanceWeightAmplitude", [&] { return one(w->GetDistanceWeightAmplitude()); } },
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
      { "SetCacheMemoryMiB", [&] { return one(w->GetCacheMemoryMiB()); } } });
  return testing::finish("TestPropertyDefaults");
}

// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTriangleSceneConverter.h"

#include "TriangleScene.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTriangleFilter.h"

#include <array>
#include <map>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkTriangleSceneConverter);

namespace
{
// The names of the material arrays, shared by the reader and the Cornell box source.
constexpr const char* DiffuseName = "Diffuse";
constexpr const char* SpecularName = "Specular";
constexpr const char* EmissionName = "Emission";
constexpr const char* MaterialIdName = "MaterialId";
constexpr const char* MaterialNamesName = "MaterialNames";

vtkSmartPointer<vtkFloatArray> ColourArray(const char* name, vtkIdType cells)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(cells);
  return array;
}

glm::vec3 Colour(vtkDataArray* array, vtkIdType cell)
{
  if (array->GetNumberOfComponents() == 1)
  {
    return glm::vec3(static_cast<float>(array->GetComponent(cell, 0)));
  }
  return glm::vec3(static_cast<float>(array->GetComponent(cell, 0)),
    static_cast<float>(array->GetComponent(cell, 1)),
    static_cast<float>(array->GetComponent(cell, 2)));
}
} // namespace

void vtkTriangleSceneConverter::ToPolyData(
  const mesolight::TriangleScene& scene, vtkPolyData* output)
{
  output->Initialize();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(scene.Positions.size()));
  for (std::size_t v = 0; v < scene.Positions.size(); ++v)
  {
    const glm::vec3& p = scene.Positions[v];
    points->SetPoint(static_cast<vtkIdType>(v), p.x, p.y, p.z);
  }
  const auto cells = static_cast<vtkIdType>(scene.Triangles.size());
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(cells, 3 * cells);
  auto diffuse = ColourArray(DiffuseName, cells);
  auto specular = ColourArray(SpecularName, cells);
  auto emission = ColourArray(EmissionName, cells);
  vtkNew<vtkIntArray> materialIds;
  materialIds->SetName(MaterialIdName);
  materialIds->SetNumberOfTuples(cells);
  for (vtkIdType t = 0; t < cells; ++t)
  {
    const glm::uvec3& triangle = scene.Triangles[static_cast<std::size_t>(t)];
    const vtkIdType ids[3] = { triangle[0], triangle[1], triangle[2] };
    polys->InsertNextCell(3, ids);
    const std::uint32_t id = scene.MaterialIds[static_cast<std::size_t>(t)];
    const mesolight::SceneMaterial& m = scene.Materials[id];
    diffuse->SetTypedTuple(t, &m.Diffuse[0]);
    specular->SetTypedTuple(t, &m.Specular[0]);
    emission->SetTypedTuple(t, &m.Emission[0]);
    materialIds->SetValue(t, static_cast<int>(id));
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetCellData()->AddArray(diffuse);
  output->GetCellData()->AddArray(specular);
  output->GetCellData()->AddArray(emission);
  output->GetCellData()->AddArray(materialIds);
  output->GetCellData()->SetActiveScalars(DiffuseName);
  vtkNew<vtkStringArray> names;
  names->SetName(MaterialNamesName);
  for (const mesolight::SceneMaterial& m : scene.Materials)
  {
    names->InsertNextValue(m.Name);
  }
  output->GetFieldData()->AddArray(names);
  if (!scene.Positions.empty() && scene.Normals.size() == scene.Positions.size())
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(points->GetNumberOfPoints());
    for (std::size_t v = 0; v < scene.Normals.size(); ++v)
    {
      normals->SetTypedTuple(static_cast<vtkIdType>(v), &scene.Normals[v][0]);
    }
    output->GetPointData()->SetNormals(normals);
  }
  if (!scene.Positions.empty() && scene.TextureCoordinates.size() == scene.Positions.size())
  {
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetName("TextureCoordinates");
    tcoords->SetNumberOfComponents(2);
    tcoords->SetNumberOfTuples(points->GetNumberOfPoints());
    for (std::size_t v = 0; v < scene.TextureCoordinates.size(); ++v)
    {
      tcoords->SetTypedTuple(static_cast<vtkIdType>(v), &scene.TextureCoordinates[v][0]);
    }
    output->GetPointData()->SetTCoords(tcoords);
  }
}

vtkSmartPointer<vtkPolyData> vtkTriangleSceneConverter::ToPolyData(
  const mesolight::TriangleScene& scene)
{
  auto output = vtkSmartPointer<vtkPolyData>::New();
  this->ToPolyData(scene, output);
  return output;
}

bool vtkTriangleSceneConverter::ToTriangleScene(vtkPolyData* input, mesolight::TriangleScene& scene)
{
  scene = mesolight::TriangleScene();
  this->LastWarningCount = 0;
  const auto warn = [this](const std::string& message)
  {
    ++this->LastWarningCount;
    vtkWarningMacro(<< message);
  };
  if (input == nullptr || input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro(<< "the input has no points or no cells: nothing to make a scene of");
    return false;
  }

  // Triangles only: polygons and strips are triangulated, vertices and lines dropped.
  vtkSmartPointer<vtkPolyData> triangles = input;
  const vtkIdType others = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkIdType nonTriangles = input->GetNumberOfStrips();
  {
    auto iterator = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCurrentCell(size, ids);
      nonTriangles += size != 3;
    }
  }
  if (others > 0 || nonTriangles > 0)
  {
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->SetInputData(input);
    triangulate->Update();
    triangles = triangulate->GetOutput();
    std::ostringstream message;
    if (nonTriangles > 0)
    {
      message << nonTriangles << " polygons/strips triangulated into "
              << triangles->GetNumberOfPolys() << " triangles in all";
    }
    if (others > 0)
    {
      message << (nonTriangles > 0 ? "; " : "") << others << " vertex/line cells ignored";
    }
    warn(message.str());
  }
  const vtkIdType cells = triangles->GetNumberOfPolys();
  if (cells == 0)
  {
    vtkErrorMacro(<< "the input has no polygons (only vertices or lines): no surfaces to light");
    return false;
  }

  vtkPoints* points = triangles->GetPoints();
  scene.Positions.resize(static_cast<std::size_t>(points->GetNumberOfPoints()));
  for (vtkIdType v = 0; v < points->GetNumberOfPoints(); ++v)
  {
    double p[3];
    points->GetPoint(v, p);
    scene.Positions[static_cast<std::size_t>(v)] = glm::vec3(p[0], p[1], p[2]);
  }
  {
    auto iterator = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCurrentCell(size, ids);
      scene.Triangles.emplace_back(ids[0], ids[1], ids[2]);
    }
  }
  // Triangles come after vertex and line cells in the cell data (none after the triangulation).
  const vtkIdType firstPoly = triangles->GetNumberOfVerts() + triangles->GetNumberOfLines();

  // Material arrays: checked, then grouped into materials.
  vtkCellData* cellData = triangles->GetCellData();
  std::array<vtkDataArray*, 3> colours = { cellData->GetArray(DiffuseName),
    cellData->GetArray(SpecularName), cellData->GetArray(EmissionName) };
  const std::array<const char*, 3> colourNames = { DiffuseName, SpecularName, EmissionName };
  std::string missing;
  for (int k = 0; k < 3; ++k)
  {
    if (colours[k] == nullptr)
    {
      missing += std::string(missing.empty() ? "" : ", ") + colourNames[k];
      continue;
    }
    const int components = colours[k]->GetNumberOfComponents();
    if (components != 1 && components != 3)
    {
      vtkErrorMacro(<< "cell array '" << colourNames[k] << "' has " << components
                    << " components; a colour needs 3 (or 1 for grey)");
      scene = mesolight::TriangleScene();
      return false;
    }
  }
  vtkDataArray* idArray = cellData->GetArray(MaterialIdName);
  for (vtkDataArray* array : { colours[0], colours[1], colours[2], idArray })
  {
    if (array && array->GetNumberOfTuples() != triangles->GetNumberOfCells())
    {
      vtkErrorMacro(<< "cell array '" << array->GetName() << "' has " << array->GetNumberOfTuples()
                    << " values for " << triangles->GetNumberOfCells() << " cells");
      scene = mesolight::TriangleScene();
      return false;
    }
  }
  if (idArray && idArray->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< "cell array 'MaterialId' has " << idArray->GetNumberOfComponents()
                  << " components, not 1");
    scene = mesolight::TriangleScene();
    return false;
  }
  if (!missing.empty())
  {
    warn("no cell array " + missing + ": defaults used (" +
      (colours[0] ? "" : "Diffuse 0.5 grey, ") + (colours[1] ? "" : "Specular 0, ") +
      (colours[2] ? "" : "Emission 0: nothing emits") + ")");
  }
  vtkStringArray* names =
    vtkStringArray::SafeDownCast(triangles->GetFieldData()->GetAbstractArray(MaterialNamesName));

  const mesolight::SceneMaterial grey = []
  {
    mesolight::SceneMaterial m;
    m.Name = "default-grey";
    m.Diffuse = glm::vec3(0.5f);
    return m;
  }();
  std::map<long long, std::uint32_t> byId;               // MaterialId -> scene material
  std::map<std::array<float, 9>, std::uint32_t> byValue; // without MaterialId
  bool warnedDiffering = false;
  for (vtkIdType t = 0; t < cells; ++t)
  {
    const vtkIdType cell = firstPoly + t;
    mesolight::SceneMaterial m = grey;
    if (colours[0])
    {
      m.Diffuse = Colour(colours[0], cell);
    }
    if (colours[1])
    {
      m.Specular = Colour(colours[1], cell);
    }
    if (colours[2])
    {
      m.Emission = Colour(colours[2], cell);
    }
    std::uint32_t material;
    if (idArray)
    {
      const auto id = static_cast<long long>(idArray->GetComponent(cell, 0));
      const auto found = byId.find(id);
      if (found == byId.end())
      {
        m.Name = (names && id >= 0 && id < names->GetNumberOfValues())
          ? names->GetValue(static_cast<vtkIdType>(id))
          : "material-" + std::to_string(id);
        material = scene.AddMaterial(m);
        byId.emplace(id, material);
      }
      else
      {
        material = found->second;
        const mesolight::SceneMaterial& first = scene.Materials[material];
        if (!warnedDiffering &&
          (first.Diffuse != m.Diffuse || first.Specular != m.Specular ||
            first.Emission != m.Emission))
        {
          warn("cells with MaterialId " + std::to_string(id) +
            " have different colours: the first cell's are used");
          warnedDiffering = true;
        }
      }
    }
    else
    {
      const std::array<float, 9> key = { m.Diffuse.x, m.Diffuse.y, m.Diffuse.z, m.Specular.x,
        m.Specular.y, m.Specular.z, m.Emission.x, m.Emission.y, m.Emission.z };
      const auto found = byValue.find(key);
      if (found == byValue.end())
      {
        if (!missing.empty() && byValue.empty() && !colours[0] && !colours[1] && !colours[2])
        {
          m.Name = grey.Name;
        }
        else
        {
          m.Name = "material-" + std::to_string(byValue.size());
        }
        material = scene.AddMaterial(m);
        byValue.emplace(key, material);
      }
      else
      {
        material = found->second;
      }
    }
    scene.MaterialIds.push_back(material);
  }

  vtkDataArray* normals = triangles->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3)
  {
    for (vtkIdType v = 0; v < points->GetNumberOfPoints(); ++v)
    {
      double n[3];
      normals->GetTuple(v, n);
      scene.Normals.emplace_back(n[0], n[1], n[2]);
    }
  }
  vtkDataArray* tcoords = triangles->GetPointData()->GetTCoords();
  if (tcoords && tcoords->GetNumberOfComponents() >= 2)
  {
    for (vtkIdType v = 0; v < points->GetNumberOfPoints(); ++v)
    {
      scene.TextureCoordinates.emplace_back(
        tcoords->GetComponent(v, 0), tcoords->GetComponent(v, 1));
    }
  }

  const mesolight::SceneCheck check = mesolight::CheckScene(scene, false);
  if (!check.Ok())
  {
    std::ostringstream message;
    for (std::size_t k = 0; k < check.Errors.size(); ++k)
    {
      message << (k ? "; " : "") << check.Errors[k];
    }
    vtkErrorMacro(<< "the input cannot be used as a scene: " << message.str());
    scene = mesolight::TriangleScene();
    return false;
  }
  for (const std::string& warning : check.Warnings)
  {
    warn(warning);
  }
  return true;
}

void vtkTriangleSceneConverter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastWarningCount: " << this->LastWarningCount << "\n";
}

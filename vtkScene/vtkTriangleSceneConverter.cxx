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

#include <glm/geometric.hpp>

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
constexpr const char* SurfaceIdName = "SurfaceId";
constexpr const char* SurfaceNamesName = "SurfaceNames";
// Each cell's Kd, Ks and Ke as one 9-component array: a Transform filter transforms the
// 3-component arrays as vectors and leaves this one alone.
constexpr const char* MaterialColoursName = "MaterialColours";

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

// The triangles of `input`: the input itself when it has only triangles, else polygons and
// strips triangulated (vtkTriangleFilter on a shallow copy: the user's data is not touched),
// vertex and line cells dropped. NonTriangles and Others count what was converted or dropped.
struct Triangles
{
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkIdType NonTriangles = 0;
  vtkIdType Others = 0;
};
Triangles Triangulate(vtkPolyData* input)
{
  Triangles out;
  out.Mesh = input;
  out.Others = input->GetNumberOfVerts() + input->GetNumberOfLines();
  out.NonTriangles = input->GetNumberOfStrips();
  auto iterator = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    out.NonTriangles += size != 3;
  }
  if (out.Others > 0 || out.NonTriangles > 0)
  {
    vtkNew<vtkPolyData> shallow;
    shallow->ShallowCopy(input);
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->SetInputData(shallow);
    triangulate->Update();
    out.Mesh = triangulate->GetOutput();
  }
  return out;
}

// Points, triangles, and the point normals (3 components, one per point) and texture
// coordinates (2 or more components) when `triangles` has them, as they are: no checks.
void CopyGeometry(vtkPolyData* triangles, mesolight::TriangleMesh& mesh)
{
  const vtkIdType count = triangles->GetNumberOfPoints();
  mesh.Positions.resize(static_cast<std::size_t>(count));
  for (vtkIdType v = 0; v < count; ++v)
  {
    double p[3];
    triangles->GetPoint(v, p);
    mesh.Positions[static_cast<std::size_t>(v)] = glm::vec3(p[0], p[1], p[2]);
  }
  auto iterator = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    if (size == 3)
    {
      mesh.Triangles.emplace_back(ids[0], ids[1], ids[2]);
    }
  }
  vtkDataArray* normals = triangles->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == count)
  {
    for (vtkIdType v = 0; v < count; ++v)
    {
      double n[3];
      normals->GetTuple(v, n);
      mesh.Normals.emplace_back(n[0], n[1], n[2]);
    }
  }
  vtkDataArray* tcoords = triangles->GetPointData()->GetTCoords();
  if (tcoords && tcoords->GetNumberOfComponents() >= 2 && tcoords->GetNumberOfTuples() == count)
  {
    for (vtkIdType v = 0; v < count; ++v)
    {
      mesh.TextureCoordinates.emplace_back(
        tcoords->GetComponent(v, 0), tcoords->GetComponent(v, 1));
    }
  }
}
} // namespace

void vtkTriangleSceneConverter::MeshToPolyData(
  const mesolight::TriangleMesh& mesh, vtkPolyData* output)
{
  output->Initialize();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.Positions.size()));
  for (std::size_t v = 0; v < mesh.Positions.size(); ++v)
  {
    const glm::vec3& p = mesh.Positions[v];
    points->SetPoint(static_cast<vtkIdType>(v), p.x, p.y, p.z);
  }
  const auto cells = static_cast<vtkIdType>(mesh.Triangles.size());
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(cells, 3 * cells);
  for (const glm::uvec3& triangle : mesh.Triangles)
  {
    const vtkIdType ids[3] = { triangle[0], triangle[1], triangle[2] };
    polys->InsertNextCell(3, ids);
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  if (!mesh.Positions.empty() && mesh.Normals.size() == mesh.Positions.size())
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(points->GetNumberOfPoints());
    for (std::size_t v = 0; v < mesh.Normals.size(); ++v)
    {
      normals->SetTypedTuple(static_cast<vtkIdType>(v), &mesh.Normals[v][0]);
    }
    output->GetPointData()->SetNormals(normals);
  }
  if (!mesh.Positions.empty() && mesh.TextureCoordinates.size() == mesh.Positions.size())
  {
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetName("TextureCoordinates");
    tcoords->SetNumberOfComponents(2);
    tcoords->SetNumberOfTuples(points->GetNumberOfPoints());
    for (std::size_t v = 0; v < mesh.TextureCoordinates.size(); ++v)
    {
      tcoords->SetTypedTuple(static_cast<vtkIdType>(v), &mesh.TextureCoordinates[v][0]);
    }
    output->GetPointData()->SetTCoords(tcoords);
  }
}

vtkSmartPointer<vtkPolyData> vtkTriangleSceneConverter::MeshToPolyData(
  const mesolight::TriangleMesh& mesh)
{
  auto output = vtkSmartPointer<vtkPolyData>::New();
  MeshToPolyData(mesh, output);
  return output;
}

void vtkTriangleSceneConverter::ToTriangleMesh(vtkPolyData* input, mesolight::TriangleMesh& mesh)
{
  mesh = mesolight::TriangleMesh();
  if (input == nullptr || input->GetNumberOfPoints() == 0)
  {
    return;
  }
  CopyGeometry(Triangulate(input).Mesh, mesh);
}

void vtkTriangleSceneConverter::ToPolyData(
  const mesolight::TriangleScene& scene, vtkPolyData* output)
{
  MeshToPolyData(scene, output);
  const auto cells = static_cast<vtkIdType>(scene.Triangles.size());
  auto diffuse = ColourArray(DiffuseName, cells);
  auto specular = ColourArray(SpecularName, cells);
  auto emission = ColourArray(EmissionName, cells);
  vtkNew<vtkIntArray> materialIds;
  materialIds->SetName(MaterialIdName);
  materialIds->SetNumberOfTuples(cells);
  vtkNew<vtkFloatArray> materialColours;
  materialColours->SetName(MaterialColoursName);
  materialColours->SetNumberOfComponents(9);
  materialColours->SetNumberOfTuples(cells);
  for (vtkIdType t = 0; t < cells; ++t)
  {
    const std::uint32_t id = scene.MaterialIds[static_cast<std::size_t>(t)];
    const mesolight::SceneMaterial& m = scene.Materials[id];
    diffuse->SetTypedTuple(t, &m.Diffuse[0]);
    specular->SetTypedTuple(t, &m.Specular[0]);
    emission->SetTypedTuple(t, &m.Emission[0]);
    materialIds->SetValue(t, static_cast<int>(id));
    const float all[9] = { m.Diffuse.x, m.Diffuse.y, m.Diffuse.z, m.Specular.x, m.Specular.y,
      m.Specular.z, m.Emission.x, m.Emission.y, m.Emission.z };
    materialColours->SetTypedTuple(t, all);
  }
  output->GetCellData()->AddArray(diffuse);
  output->GetCellData()->AddArray(specular);
  output->GetCellData()->AddArray(emission);
  output->GetCellData()->AddArray(materialIds);
  output->GetCellData()->AddArray(materialColours);
  output->GetCellData()->SetActiveScalars(DiffuseName);
  vtkNew<vtkStringArray> names;
  names->SetName(MaterialNamesName);
  for (const mesolight::SceneMaterial& m : scene.Materials)
  {
    names->InsertNextValue(m.Name);
  }
  output->GetFieldData()->AddArray(names);
  if (!scene.SurfaceIds.empty())
  {
    vtkNew<vtkIntArray> surfaceIds;
    surfaceIds->SetName(SurfaceIdName);
    surfaceIds->SetNumberOfTuples(cells);
    for (vtkIdType t = 0; t < cells; ++t)
    {
      const std::uint32_t id = scene.SurfaceIds[static_cast<std::size_t>(t)];
      surfaceIds->SetValue(
        t, id == mesolight::TriangleScene::NoSurface ? -1 : static_cast<int>(id));
    }
    output->GetCellData()->AddArray(surfaceIds);
    vtkNew<vtkStringArray> surfaceNames;
    surfaceNames->SetName(SurfaceNamesName);
    for (const std::string& name : scene.SurfaceNames)
    {
      surfaceNames->InsertNextValue(name);
    }
    output->GetFieldData()->AddArray(surfaceNames);
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
  const Triangles triangulated = Triangulate(input);
  vtkPolyData* triangles = triangulated.Mesh;
  if (triangulated.Others > 0 || triangulated.NonTriangles > 0)
  {
    std::ostringstream message;
    if (triangulated.NonTriangles > 0)
    {
      message << triangulated.NonTriangles << " polygons/strips triangulated into "
              << triangles->GetNumberOfPolys() << " triangles in all";
    }
    if (triangulated.Others > 0)
    {
      message << (triangulated.NonTriangles > 0 ? "; " : "") << triangulated.Others
              << " vertex/line cells ignored";
    }
    warn(message.str());
  }
  const vtkIdType cells = triangles->GetNumberOfPolys();
  if (cells == 0)
  {
    vtkErrorMacro(<< "the input has no polygons (only vertices or lines): no surfaces to light");
    return false;
  }

  CopyGeometry(triangles, scene);
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
  // ToPolyData's 9-component MaterialColours is what the 3-component arrays were made from. A
  // Transform filter (ParaView's transforms every 3-component array by default) scales and
  // rotates those as if they were vectors and leaves this one alone, which vtkAppendPolyData
  // appends like any cell array: where it is, it gives the colours, and cells whose 3-component
  // arrays differ are said.
  vtkDataArray* materialColours = cellData->GetArray(MaterialColoursName);
  if (materialColours &&
    (materialColours->GetNumberOfComponents() != 9 ||
      materialColours->GetNumberOfTuples() != triangles->GetNumberOfCells()))
  {
    warn("cell array 'MaterialColours' is not 9 values per cell: the Diffuse, Specular and "
         "Emission arrays are used");
    materialColours = nullptr;
  }
  vtkIdType cellsDisagreeing = 0;

  const mesolight::SceneMaterial grey = []
  {
    mesolight::SceneMaterial m;
    m.Name = "default-grey";
    m.Diffuse = glm::vec3(0.5f);
    return m;
  }();
  // A cell's own colours (the grey defaults where an array is missing), as a key and a material.
  const auto cellMaterial = [&](vtkIdType cell, bool count)
  {
    mesolight::SceneMaterial m = grey;
    if (materialColours)
    {
      double all[9];
      materialColours->GetTuple(cell, all);
      m.Diffuse = glm::vec3(glm::dvec3(all[0], all[1], all[2]));
      m.Specular = glm::vec3(glm::dvec3(all[3], all[4], all[5]));
      m.Emission = glm::vec3(glm::dvec3(all[6], all[7], all[8]));
      const float tolerance = 1e-5f * (1.0f + glm::length(m.Emission));
      if ((colours[0] && glm::length(Colour(colours[0], cell) - m.Diffuse) > tolerance) ||
        (colours[1] && glm::length(Colour(colours[1], cell) - m.Specular) > tolerance) ||
        (colours[2] && glm::length(Colour(colours[2], cell) - m.Emission) > tolerance))
      {
        cellsDisagreeing += count ? 1 : 0;
      }
      return m;
    }
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
    return m;
  };
  const auto keyOf = [](const mesolight::SceneMaterial& m)
  {
    return std::array<float, 9>{ m.Diffuse.x, m.Diffuse.y, m.Diffuse.z, m.Specular.x, m.Specular.y,
      m.Specular.z, m.Emission.x, m.Emission.y, m.Emission.z };
  };
  // The cells of one MaterialId agree on their colours in a scene as ToPolyData wrote it. Where
  // they do not, ids of different scenes collide (two scenes appended, each numbering its
  // materials from 0): such an id's cells keep their own colours, one material per colour.
  std::map<long long, std::pair<std::array<float, 9>, bool>> idColours; // first cell's, collided
  if (idArray)
  {
    for (vtkIdType t = 0; t < cells; ++t)
    {
      const vtkIdType cell = firstPoly + t;
      const auto id = static_cast<long long>(idArray->GetComponent(cell, 0));
      const std::array<float, 9> key = keyOf(cellMaterial(cell, false));
      const auto found = idColours.find(id);
      if (found == idColours.end())
      {
        idColours.emplace(id, std::make_pair(key, false));
      }
      else if (found->second.first != key)
      {
        found->second.second = true;
      }
    }
  }
  // (MaterialId, the cell's colours for a collided id) -> scene material.
  std::map<std::pair<long long, std::array<float, 9>>, std::uint32_t> byId;
  std::map<long long, int> groupsOfId;
  std::map<std::array<float, 9>, std::uint32_t> byValue; // without MaterialId
  std::string collided;
  for (vtkIdType t = 0; t < cells; ++t)
  {
    const vtkIdType cell = firstPoly + t;
    mesolight::SceneMaterial m = cellMaterial(cell, true);
    std::uint32_t material;
    if (idArray)
    {
      const auto id = static_cast<long long>(idArray->GetComponent(cell, 0));
      const bool collides = idColours[id].second;
      const auto key = std::make_pair(id, collides ? keyOf(m) : std::array<float, 9>{});
      const auto found = byId.find(key);
      if (found == byId.end())
      {
        m.Name = (names && id >= 0 && id < names->GetNumberOfValues())
          ? names->GetValue(static_cast<vtkIdType>(id))
          : "material-" + std::to_string(id);
        const int group = ++groupsOfId[id];
        if (group > 1)
        {
          m.Name += "-" + std::to_string(group);
          if (group == 2)
          {
            collided += (collided.empty() ? "" : ", ") + std::to_string(id);
          }
        }
        material = scene.AddMaterial(m);
        byId.emplace(key, material);
      }
      else
      {
        material = found->second;
      }
    }
    else
    {
      const std::array<float, 9> key = keyOf(m);
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
  if (!collided.empty())
  {
    warn("cells with MaterialId " + collided +
      " have different colours (scenes appended, whose material ids collide?): each colour is "
      "a material of its own");
  }
  if (cellsDisagreeing > 0)
  {
    warn(std::to_string(cellsDisagreeing) + " of " + std::to_string(cells) +
      " cells' Diffuse, Specular or Emission arrays differ from their MaterialColours: "
      "MaterialColours are used. A Transform filter scales and rotates every 3-component array "
      "as a vector unless its Transform All Input Vectors is off; the materials stay right "
      "either way");
  }
  // Surface names, when the polydata carries them (ToPolyData's): ids outside the names are
  // unnamed.
  vtkDataArray* surfaceIds = cellData->GetArray(SurfaceIdName);
  vtkStringArray* surfaceNames =
    vtkStringArray::SafeDownCast(triangles->GetFieldData()->GetAbstractArray(SurfaceNamesName));
  if (surfaceIds && surfaceNames && surfaceIds->GetNumberOfComponents() == 1 &&
    surfaceIds->GetNumberOfTuples() == firstPoly + cells)
  {
    for (vtkIdType k = 0; k < surfaceNames->GetNumberOfValues(); ++k)
    {
      scene.SurfaceNames.push_back(surfaceNames->GetValue(k));
    }
    scene.SurfaceIds.resize(static_cast<std::size_t>(cells), mesolight::TriangleScene::NoSurface);
    for (vtkIdType t = 0; t < cells; ++t)
    {
      const double id = surfaceIds->GetComponent(firstPoly + t, 0);
      if (id >= 0.0 && id < static_cast<double>(scene.SurfaceNames.size()))
      {
        scene.SurfaceIds[static_cast<std::size_t>(t)] = static_cast<std::uint32_t>(id);
      }
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

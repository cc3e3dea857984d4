// Reads mesh files (.ply, .obj, .glb) and checks that every vertex normal faces the side its
// triangles' winding shows: for each triangle with area, each of its three vertex normals is
// unit length and within 90 degrees of the triangle's geometric normal (computed here in double
// from the file's positions, counter-clockwise). Prints one line per file; exit 1 on any failure.
// With --from-voxels it first meshes the densities and materials `voxc run --voxels --materials`
// wrote, with both host meshers, into every format (DIR/{mc,sn}.{ply,obj,glb}), and checks those.
// Usage: voxc_normals_check [--from-voxels DENSITY.npy MATERIALS.npy DIR] FILE...
#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/MarchingCubes.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    std::vector<std::string> files(argv + 1, argv + argc);
    if (files.size() >= 4 && files[0] == "--from-voxels") {
        try {
            voxc::DenseGrid dense = voxc::readNpy(files[1]);
            voxc::readMaterialNpy(files[2], dense);
            const voxc::ChunkedGrid grid = voxc::ChunkedGrid::fromDense(dense, voxc::ChunkLayout::make(glm::ivec3(0), dense.size(), 32));
            const std::string dir = files[3];
            files.erase(files.begin(), files.begin() + 4);
            for (const char* mesher : {"mc", "sn"}) {
                const voxc::Mesh mesh = std::strcmp(mesher, "mc") == 0 ? voxc::meshMarchingCubes(grid, voxc::MeshOptions{})
                                                                      : voxc::meshSurfaceNets(grid, voxc::MeshOptions{});
                for (const char* ext : {".ply", ".obj", ".glb"}) {
                    files.push_back(dir + "/" + mesher + ext);
                    voxc::writeMesh(files.back(), mesh);
                }
            }
        } catch (const std::exception& e) {
            std::printf("FAIL meshing %s: %s\n", argv[2], e.what());
            return 1;
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: voxc_normals_check [--from-voxels DENSITY.npy MATERIALS.npy DIR] FILE...\n");
        return 1;
    }
    int failed = 0;
    for (size_t i = 0; i < files.size(); ++i) {
        const char* path = files[i].c_str();
        voxc::Mesh mesh;
        try {
            mesh = voxc::readMesh(path);
        } catch (const std::exception& e) {
            std::printf("FAIL %s: %s\n", path, e.what());
            ++failed;
            continue;
        }
        size_t against = 0, checked = 0, notUnit = 0, firstAgainst = SIZE_MAX;
        for (const glm::vec3& n : mesh.normals) {
            const double length = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
            if (!(std::abs(length - 1.0) < 1e-3)) ++notUnit;
        }
        for (size_t t = 0; t < mesh.triangles.size() / 3; ++t) {
            const glm::dvec3 a(mesh.positions[mesh.triangles[t * 3]]), b(mesh.positions[mesh.triangles[t * 3 + 1]]),
                c(mesh.positions[mesh.triangles[t * 3 + 2]]);
            const glm::dvec3 e1 = b - a, e2 = c - a;
            const glm::dvec3 face(e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x);
            if (face == glm::dvec3(0.0)) continue;
            ++checked;
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 n(mesh.normals[mesh.triangles[t * 3 + size_t(k)]]);
                if (n.x * face.x + n.y * face.y + n.z * face.z < 0.0) {
                    if (firstAgainst == SIZE_MAX) firstAgainst = t;
                    ++against;
                    break;
                }
            }
        }
        if (checked == 0 || against > 0 || notUnit > 0) {
            ++failed;
            std::printf("FAIL %s: %zu of %zu triangles have a vertex normal more than 90 degrees from their winding's normal"
                        " (first: triangle %zu), %zu normals not unit length\n",
                        path, against, checked, firstAgainst == SIZE_MAX ? 0 : firstAgainst, notUnit);
        } else {
            std::printf("ok   %s: %zu triangles, every vertex normal within 90 degrees of its triangles' normals\n", path, checked);
        }
    }
    return failed ? 1 : 0;
}

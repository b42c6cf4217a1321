// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`): meshes are written as their arrays and read back through
//! their checked constructors ([`TriangleMesh::try_new`], [`PolyMesh::try_new`]).

use glam::{DVec2, DVec3};
use serde::de::{Deserialize, Deserializer, Error as _};
use serde::ser::{Serialize, Serializer};
use serde::{Deserialize as DeriveDeserialize, Serialize as DeriveSerialize};

use crate::colormap::{ColorLegend, ColorMapping};
use crate::{PolyMesh, TriangleMesh};

#[derive(DeriveSerialize)]
struct TriangleMeshRef<'a> {
    positions: &'a [DVec3],
    normals: &'a [DVec3],
    uvs: &'a [DVec2],
    triangles: &'a [[u32; 3]],
    #[serde(skip_serializing_if = "Option::is_none")]
    colors: Option<&'a [[f32; 3]]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    legend: Option<&'a ColorLegend>,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct TriangleMeshOwned {
    positions: Vec<DVec3>,
    normals: Vec<DVec3>,
    uvs: Vec<DVec2>,
    triangles: Vec<[u32; 3]>,
    #[serde(default)]
    colors: Option<Vec<[f32; 3]>>,
    #[serde(default)]
    legend: Option<ColorLegend>,
}

impl Serialize for TriangleMesh {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        TriangleMeshRef {
            positions: self.positions(),
            normals: self.normals(),
            uvs: self.uvs(),
            triangles: self.triangles(),
            colors: self.colors(),
            legend: self.legend(),
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for TriangleMesh {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = TriangleMeshOwned::deserialize(deserializer)?;
        let mesh = TriangleMesh::try_new(raw.positions, raw.normals, raw.uvs, raw.triangles)
            .map_err(D::Error::custom)?;
        match (raw.colors, raw.legend) {
            (None, None) => Ok(mesh),
            (Some(colors), None) => mesh.try_with_colors(colors).map_err(D::Error::custom),
            (Some(colors), Some(legend)) => {
                mesh.try_with_mapping(ColorMapping { colors, legend }).map_err(D::Error::custom)
            }
            (None, Some(_)) => Err(D::Error::custom("a mesh with a colour legend has no colours")),
        }
    }
}

#[derive(DeriveSerialize)]
struct PolyMeshRef<'a> {
    positions: &'a [DVec3],
    faces: Vec<&'a [u32]>,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct PolyMeshOwned {
    positions: Vec<DVec3>,
    faces: Vec<Vec<u32>>,
}

impl Serialize for PolyMesh {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        PolyMeshRef { positions: self.positions(), faces: self.faces().collect() }
            .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for PolyMesh {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = PolyMeshOwned::deserialize(deserializer)?;
        PolyMesh::try_new(raw.positions, &raw.faces).map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ColorMap;
    use crate::subdivision::Scheme;

    fn round_trip<T: Serialize + serde::de::DeserializeOwned>(value: &T) -> T {
        serde_json::from_str(&serde_json::to_string(value).unwrap()).unwrap()
    }

    fn tetrahedron() -> PolyMesh {
        let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
        PolyMesh::try_new(p, &[[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]).unwrap()
    }

    #[test]
    fn meshes_read_back_equal() {
        let poly = tetrahedron();
        assert_eq!(round_trip(&poly), poly);
        let mesh = poly.to_triangle_mesh().unwrap();
        assert_eq!(round_trip(&mesh), mesh);
        let values: Vec<f64> = (0..mesh.n_vertices()).map(|i| i as f64 - 1.5).collect();
        let mapping = ColorMap::default().try_apply(&values).unwrap();
        let coloured = mesh.clone().try_with_mapping(mapping).unwrap();
        assert_eq!(round_trip(&coloured), coloured);
        let scheme = Scheme::CatmullClark;
        assert_eq!(serde_json::to_string(&scheme).unwrap(), r#""catmull_clark""#);
        assert_eq!(round_trip(&scheme), scheme);
    }

    #[test]
    fn invalid_meshes_are_errors() {
        for (text, what) in [
            (r#"{"positions":[[0,0,0]],"faces":[[0,1,2]]}"#, "an index out of range"),
            (r#"{"positions":[[0,0,0],[1,0,0],[0,1,0]],"faces":[[0,1]]}"#, "a two-sided face"),
        ] {
            assert!(serde_json::from_str::<PolyMesh>(text).is_err(), "{what}");
        }
        let one = r#"{"positions":[[0,0,0],[1,0,0],[0,1,0]],"normals":[[0,0,1],[0,0,1],[0,0,2]],"uvs":[[0,0],[0,0],[0,0]],"triangles":[[0,1,2]]}"#;
        let err = serde_json::from_str::<TriangleMesh>(one).unwrap_err().to_string();
        assert!(err.contains("normal"), "{err}");
    }
}

// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`): scans, repairs and distance summaries are plain data and
//! derive their forms; these tests check that they read back equal and that a summary leaves
//! its per-point distances out.

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use crate::distance::Distances;
    use crate::repair::Repair;
    use crate::scan::Scan;

    #[test]
    fn scans_and_reports_read_back_equal() {
        let scan = Scan {
            points: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            normals: Some(vec![DVec3::Z; 3]),
            triangles: vec![[0, 1, 2]],
            dropped_points: 1,
            dropped_faces: 0,
        };
        let text = serde_json::to_string(&scan).unwrap();
        assert_eq!(serde_json::from_str::<Scan>(&text).unwrap(), scan);
        let repair = Repair { holes: 2, hole_edges: 9, ..Repair::default() };
        let text = serde_json::to_string(&repair).unwrap();
        assert_eq!(serde_json::from_str::<Repair>(&text).unwrap(), repair);
    }

    #[test]
    fn a_summary_is_written_without_its_per_point_distances() {
        let d = Distances::from_values(vec![0.0, 3.0, 4.0], 10.0);
        let json = serde_json::to_value(&d).unwrap();
        assert_eq!(json["max"], 4.0, "{json}");
        assert!(json.get("per_point").is_none(), "{json}");
    }
}

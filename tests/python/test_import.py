"""ceilplan.import_map: `ceilplan import` from Python. Polygon meshes, the open/closed rule, the crop,
and the summary's free-space line; bad options refused before anything is read or written."""

import json

import pytest

import ceilplan

# A box 2 x 2 x 1.8 m as six quads, counter-clockwise seen from outside.
CORNERS = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 1.8), (2, 0, 1.8), (2, 2, 1.8), (0, 2, 1.8)]
QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


def write_obj(path, quads):
    lines = ["v %g %g %g" % corner for corner in CORNERS]
    lines += ["f " + " ".join(str(i + 1) for i in quad) for quad in quads]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_closed_quad_mesh_is_filled_and_a_crop_limits_the_map(tmp_path):
    mesh = write_obj(tmp_path / "box.obj", QUADS)
    summary = ceilplan.import_map(tmp_path / "box.bt", mesh=mesh, resolution_m=0.1, crop=(1, -1, -1, 4, 4, 4))
    assert summary["kind"] == "mesh"
    assert summary["free_space"].startswith("closed mesh, triangles facing outward: solid, interior filled;")
    assert "(cropped to (1.00, -1.00, -1.00) to (4.00, 4.00, 4.00))" in summary["free_space"]
    assert summary["crop_m"] == {"min": [1.0, -1.0, -1.0], "max": [4.0, 4.0, 4.0]}
    assert summary["extent_m"]["min"][0] == pytest.approx(1.0)
    assert summary["figures"]["triangles"] == 12
    assert summary["figures"]["enclosed_voxels"] > 0  # the half the crop keeps is still filled
    written = json.loads((tmp_path / "box.bt.json").read_text())
    assert written["free_space"] == summary["free_space"]
    assert (tmp_path / "box.bt").stat().st_size > 0


def test_an_open_mesh_is_a_thin_shell(tmp_path):
    # Floor, roof and the walls at x = 0 and x = 2: a tube along y, open at both ends.
    tube = write_obj(tmp_path / "tube.obj", [QUADS[0], QUADS[1], QUADS[3], QUADS[5]])
    summary = ceilplan.import_map(tmp_path / "tube.bt", mesh=tube, resolution_m=0.1)
    assert "so not watertight): thin shell, both sides free;" in summary["free_space"]
    assert "planning may use both sides of every surface" in summary["free_space"]


def test_a_cloud_alone_vouches_only_for_space_between_its_surfaces(tmp_path):
    # A floor 4 x 2 m and a ceiling 2 m up over its first 2 m only, 5 cm apart.
    rows = ["%.3f %.3f 0.013" % (0.01 + 0.05 * i, 0.01 + 0.05 * j) for i in range(80) for j in range(40)]
    rows += ["%.3f %.3f 2.033" % (0.01 + 0.05 * i, 0.01 + 0.05 * j) for i in range(40) for j in range(40)]
    cloud = tmp_path / "hall.xyz"
    cloud.write_text("\n".join(rows) + "\n")
    between = ceilplan.import_map(tmp_path / "between.bt", points=cloud, resolution_m=0.1, free_distance_m=0.0)
    assert "with a point above and below it in its column is free" in between["free_space"]
    assert "the cloud says nothing, so that space is unknown" in between["free_space"]
    box = ceilplan.import_map(tmp_path / "box.bt", points=cloud, resolution_m=0.1, free_distance_m=0.0, free_region="box")
    assert "behind walls and beside the structure too" in box["free_space"]
    # Free only under the ceiling: half the air the whole box calls free.
    assert between["figures"]["free_m3"] == pytest.approx(box["figures"]["free_m3"] / 2, rel=0.1)


@pytest.mark.parametrize(
    "options, says",
    [
        ({"crop": (0, 0, 0, 1, 1)}, "crop must be (xmin, ymin, zmin, xmax, ymax, zmax)"),
        ({"crop": (0, 0, 2, 1, 1, 1)}, "a crop box's z minimum (2) must be below its maximum (1)"),
        ({"crop": (float("nan"), 0, 0, 1, 1, 1)}, "a crop box needs finite corners"),
        ({"max_range_m": -1.0}, "a maximum range of -1 m"),
        ({"interior": "porous"}, "use auto, solid, hollow or shell"),
        ({"free_region": "hull"}, "unknown free region 'hull': use between or box"),
    ],
)
def test_bad_options_are_refused_before_anything_is_written(tmp_path, options, says):
    mesh = write_obj(tmp_path / "box.obj", QUADS)
    with pytest.raises(ceilplan.InputError) as refused:
        ceilplan.import_map(tmp_path / "box.bt", mesh=mesh, **options)
    assert says in str(refused.value)
    assert isinstance(refused.value, ValueError)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["box.obj"]


def test_progress_reports_the_import_and_an_exception_from_it_cancels_with_nothing_written(tmp_path):
    mesh = write_obj(tmp_path / "box.obj", QUADS)
    reports = []
    ceilplan.import_map(tmp_path / "box.bt", mesh=mesh, resolution_m=0.1,
                        progress=lambda stage, fraction: reports.append((stage, fraction)))
    assert reports and all(isinstance(stage, str) and 0.0 <= fraction <= 1.0 for stage, fraction in reports)

    class Stop(Exception):
        pass

    def stop(stage, fraction):
        raise Stop(stage)

    with pytest.raises(Stop):
        ceilplan.import_map(tmp_path / "again.bt", mesh=mesh, resolution_m=0.1, progress=stop)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["box.bt", "box.bt.json", "box.obj"]

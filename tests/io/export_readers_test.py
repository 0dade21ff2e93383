#!/usr/bin/python3
"""A tour's flight exports read back by independent readers, never by ceilplan's own code.

- mission.plan against QGroundControl's required keys and MAVLink's common.xml commands
  (tests/data/export_references/qgc_plan_keys.json, mavlink_commands.json);
- mission.waypoints as QGroundControl's MissionItem::load reads WPL 110 rows;
- routes.kml and routes.geojson through GDAL/OGR;
- mission.kmz unzipped with zipfile, its XML parsed with ElementTree and checked element by
  element against DJI's WPML tables (tests/data/export_references/dji_wpml_tables.json).

What a pilot needs of them (docs/flying.md): the speed commanded from the first leg on, a
take-off first and a landing last, WPML's required elements, enumerations and ranges, and no
photo where the plan takes a contact reading.

Usage: export_readers_test.py [--autopilot px4|ardupilot] [--expect-kmz] TOUR_DIR...
A TOUR_DIR holds tour.json (one mode) or ceiling/ and free/ (both). Prints each check and
"N passed, N failed"; exits 1 on any failure.
"""

import argparse
import json
import math
import os
import sys
import xml.etree.ElementTree as ET
import zipfile

from osgeo import ogr

REFERENCES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "export_references")
MAVLINK = json.load(open(os.path.join(REFERENCES, "mavlink_commands.json")))
QGC = json.load(open(os.path.join(REFERENCES, "qgc_plan_keys.json")))
WPML = json.load(open(os.path.join(REFERENCES, "dji_wpml_tables.json")))
KML_NS = "http://www.opengis.net/kml/2.2"

NAV_WAYPOINT, NAV_LAND, NAV_TAKEOFF, DO_CHANGE_SPEED, IMAGE_START_CAPTURE = 16, 21, 22, 178, 2000


class Checks:
    def __init__(self):
        self.passed = 0
        self.failed = []

    def check(self, condition, what):
        if condition:
            self.passed += 1
        else:
            self.failed.append(what)
            print("FAIL: " + what)
        return condition


def type_matches(value, spec):
    kind, _, expected = spec.partition(":")
    if kind == "string":
        return isinstance(value, str) and (not expected or value == expected)
    if kind == "number":
        return isinstance(value, (int, float)) and not isinstance(value, bool) and (not expected or value == float(expected))
    if kind == "bool":
        return isinstance(value, bool)
    if kind == "object":
        return isinstance(value, dict)
    if kind == "array":
        return isinstance(value, list) and (not expected or len(value) == int(expected))
    raise ValueError(spec)


def check_keys(checks, obj, table, where):
    for key, spec in table.get("required", {}).items():
        checks.check(key in obj and type_matches(obj[key], spec), f"{where}: required key '{key}' ({spec})")
    for key, spec in table.get("optional", {}).items():
        if key in obj:
            checks.check(type_matches(obj[key], spec), f"{where}: key '{key}' is {spec}")


def route_points(geojson_path):
    """Each sortie's waypoints as GDAL reads them: {sortie: [(index, lon, lat, properties)]}."""
    source = ogr.Open(geojson_path)
    points = {}
    for layer in source:
        for feature in layer:
            geometry = feature.GetGeometryRef()
            if geometry.GetGeometryName() != "POINT" or feature.GetField("index") is None:
                continue
            properties = {feature.GetFieldDefnRef(i).GetName(): feature.GetField(i) for i in range(feature.GetFieldCount())}
            points.setdefault(properties["sortie"], []).append(
                (properties["index"], geometry.GetX(), geometry.GetY(), properties))
    return {sortie: sorted(list_) for sortie, list_ in points.items()}


def sortie_file(directory, name, sortie, count):
    stem, extension = os.path.splitext(name)
    return os.path.join(directory, name if count == 1 else f"{stem}_sortie{sortie}{extension}")


def check_plan(checks, path, autopilot, waypoints, sortie):
    plan = json.load(open(path))
    check_keys(checks, plan, QGC["plan"], path)
    mission = plan.get("mission", {})
    check_keys(checks, mission, QGC["mission"], path + ": mission")
    checks.check(mission.get("firmwareType") == (3 if autopilot == "ardupilot" else 12), f"{path}: firmwareType for {autopilot}")
    items = mission.get("items", [])
    for k, item in enumerate(items):
        where = f"{path}: item {k + 1}"
        check_keys(checks, item, QGC["simple_item"], where)
        command = MAVLINK["commands"].get(str(item["command"]))
        if not checks.check(command is not None, f"{where}: command {item['command']} is one of common.xml's"):
            continue
        checks.check(str(item["frame"]) in MAVLINK["frames"], f"{where}: frame {item['frame']} in MAV_FRAME")
        for index, param in command["params"].items():
            value = item["params"][int(index) - 1]
            label = f"{where} ({command['name']}) param {index} {param.get('label', '')}"
            if param.get("reserved") == "true":
                default = param.get("default", "0")
                expected_null = default == "NaN"
                checks.check((value is None) if expected_null else value == float(default), f"{label}: reserved, {default}")
            if value is not None and "minValue" in param:
                checks.check(value >= float(param["minValue"]), f"{label}: {value} >= minValue {param['minValue']}")
            if value is not None and "maxValue" in param:
                checks.check(value <= float(param["maxValue"]), f"{label}: {value} <= maxValue {param['maxValue']}")
    commands = [item["command"] for item in items]
    checks.check(commands[:1] == [NAV_TAKEOFF] and items[0]["params"][6] > 0,
                 f"{path}: the first item takes off (NAV_TAKEOFF to a height above home)")
    first_waypoint = commands.index(NAV_WAYPOINT)
    checks.check(DO_CHANGE_SPEED in commands[:first_waypoint] and
                 items[commands.index(DO_CHANGE_SPEED)]["params"][1] > 0,
                 f"{path}: a speed is commanded before the first waypoint (cruiseSpeed never reaches the vehicle)")
    if sortie.get("landing_height_m") is not None:
        checks.check(commands[-1] == NAV_LAND, f"{path}: a route that ends at home ends with NAV_LAND")
    # Per waypoint: the items from its NAV_WAYPOINT to the next.
    starts = [k for k, c in enumerate(commands) if c == NAV_WAYPOINT]
    checks.check(len(starts) == len(waypoints), f"{path}: one NAV_WAYPOINT per route waypoint ({len(starts)} vs {len(waypoints)})")
    for (index, lon, lat, properties), start, end in zip(waypoints, starts, starts[1:] + [len(items)]):
        following = commands[start + 1:end]
        params = items[start]["params"]
        where = f"{path}: waypoint {index}"
        checks.check(abs(params[4] - lat) < 1e-7 and abs(params[5] - lon) < 1e-7,
                     f"{where}: at GDAL's GeoJSON position ({params[4]}, {params[5]}) vs ({lat}, {lon})")
        if properties.get("contact_reading"):
            checks.check(IMAGE_START_CAPTURE not in following, f"{where}: a contact reading takes no photo")
            checks.check(abs(params[0] - properties["hold_s"]) < 1e-9 and params[0] > 0,
                         f"{where}: a contact reading hovers its dwell ({params[0]} s)")
        checks.check((IMAGE_START_CAPTURE in following) == bool(properties.get("take_photo")),
                     f"{where}: a photo command exactly where the route takes a photo")
    return items


def check_wpl(checks, path, items, autopilot):
    lines = open(path).read().splitlines()
    checks.check(lines[:1] == [QGC["wpl"]["header"]], f"{path}: header {QGC['wpl']['header']}")
    rows = [line.split("\t") for line in lines[1:]]
    checks.check(all(len(row) == QGC["wpl"]["fields"] for row in rows), f"{path}: {QGC['wpl']['fields']} TAB-separated fields a row")
    checks.check(len(rows) == len(items) + 1, f"{path}: home and one row per .plan item")
    checks.check([int(row[3]) for row in rows[1:]] == [item["command"] for item in items], f"{path}: the .plan's commands in order")
    if autopilot == "ardupilot":
        # ArduCopter refuses AUTO from the ground unless its first command takes off
        # (ArduCopter/mode_auto.cpp, "Missing Takeoff Cmd").
        checks.check(int(rows[1][3]) == NAV_TAKEOFF, f"{path}: ArduPilot's first command is NAV_TAKEOFF")


def check_geo(checks, directory, tour):
    for name, drivers in (("routes.kml", ("KML", "LIBKML")), ("routes.geojson", ("GeoJSON",))):
        path = os.path.join(directory, name)
        source = ogr.Open(path)
        if not checks.check(source is not None, f"{path}: GDAL/OGR opens it"):
            continue
        checks.check(source.GetDriver().GetName() in drivers, f"{path}: read by GDAL's {drivers[0]} driver")
        points = lines = 0
        for layer in source:
            for feature in layer:
                geometry = feature.GetGeometryRef()
                points += geometry.GetGeometryName() == "POINT"
                lines += geometry.GetGeometryName() == "LINESTRING"
                checks.check(geometry.IsValid(), f"{path}: feature {feature.GetFID()} is a valid geometry")
        checks.check(lines == len(tour["sorties"]), f"{path}: one line per sortie ({lines})")
        checks.check(points > len(tour["sorties"]), f"{path}: waypoints as points ({points})")


def wpml_children(element):
    return [child.tag.replace("{" + WPML["namespace"] + "}", "wpml:").replace("{" + KML_NS + "}", "") for child in element]


def wpml_text(element, name):
    found = element.find(name.replace("wpml:", "{" + WPML["namespace"] + "}"))
    return None if found is None else (found.text or "").strip()


def condition_holds(element, condition, root):
    name, _, values = condition.partition("=")
    scope = root if name.startswith("template:") else element
    value = None
    for candidate in scope.iter(name.replace("template:", "").replace("wpml:", "{" + WPML["namespace"] + "}")):
        value = (candidate.text or "").strip()
        break
    return value in values.split("|")


def check_wpml_element(checks, element, table_name, root, where):
    table = WPML["parents"][table_name]
    children = wpml_children(element)
    for name in table["required"]:
        checks.check(name in children, f"{where}: required {name}")
    for name, condition in table.get("conditional", {}).items():
        if condition_holds(element, condition, root):
            checks.check(name in children, f"{where}: {name} required when {condition}")
    known = set(table["required"]) | set(table.get("optional", [])) | set(table.get("conditional", {}))
    for name in children:
        checks.check(name in known, f"{where}: {name} is an element DJI defines here")
    for child, name in zip(element, children):
        text = (child.text or "").strip()
        if name in WPML["enums"]:
            checks.check(text in WPML["enums"][name], f"{where}: {name} '{text}' in {WPML['enums'][name]}")
        if name in WPML["ranges"]:
            low, high, *mode = WPML["ranges"][name]
            value = float(text)
            inside = (value > low if mode else value >= low) and (high is None or value <= high)
            checks.check(inside, f"{where}: {name} {value} within [{low}, {high}]")


def check_kmz(checks, path, waypoints):
    with zipfile.ZipFile(path) as archive:
        names = archive.namelist()
        checks.check("wpmz/template.kml" in names and "wpmz/waylines.wpml" in names, f"{path}: wpmz/template.kml and waylines.wpml")
        checks.check(archive.testzip() is None, f"{path}: every member's CRC holds")
        documents = {kind: ET.fromstring(archive.read(f"wpmz/{file}"))
                     for kind, file in (("template", "template.kml"), ("waylines", "waylines.wpml"))}
    ns = {"kml": KML_NS, "wpml": WPML["namespace"]}
    for kind, root in documents.items():
        where = f"{path}:{kind}"
        document = root.find("kml:Document", ns)
        check_wpml_element(checks, document, f"{kind}:Document", root, where)
        config = document.find("wpml:missionConfig", ns)
        check_wpml_element(checks, config, "wpml:missionConfig", root, where + " missionConfig")
        check_wpml_element(checks, config.find("wpml:droneInfo", ns), "wpml:droneInfo", root, where + " droneInfo")
        check_wpml_element(checks, config.find("wpml:payloadInfo", ns), "wpml:payloadInfo", root, where + " payloadInfo")
        drone = wpml_text(config.find("wpml:droneInfo", ns), "wpml:droneEnumValue") + "-" + (
            wpml_text(config.find("wpml:droneInfo", ns), "wpml:droneSubEnumValue") or "0")
        checks.check(drone in WPML["products"]["drones"], f"{where}: drone {drone} in DJI's product table")
        checks.check(wpml_text(config.find("wpml:payloadInfo", ns), "wpml:payloadEnumValue") in WPML["products"]["payloads"],
                     f"{where}: payload in DJI's product table")
        folder = document.find("kml:Folder", ns)
        check_wpml_element(checks, folder, f"{kind}:Folder", root, where + " Folder")
        if folder.find("wpml:waylineCoordinateSysParam", ns) is not None:
            check_wpml_element(checks, folder.find("wpml:waylineCoordinateSysParam", ns), "wpml:waylineCoordinateSysParam", root,
                               where + " waylineCoordinateSysParam")
        if folder.find("wpml:globalWaypointHeadingParam", ns) is not None:
            check_wpml_element(checks, folder.find("wpml:globalWaypointHeadingParam", ns), "wpml:globalWaypointHeadingParam",
                               root, where + " globalWaypointHeadingParam")
        placemarks = folder.findall("kml:Placemark", ns)
        checks.check([int(wpml_text(p, "wpml:index")) for p in placemarks] == list(range(len(placemarks))),
                     f"{where}: wpml:index from 0, one by one")
        checks.check(len(placemarks) == len(waypoints), f"{where}: one Placemark per route waypoint")
        for placemark, (index, lon, lat, properties) in zip(placemarks, waypoints):
            at = f"{where} Placemark {index}"
            check_wpml_element(checks, placemark, f"{kind}:Placemark", root, at)
            coordinates = [float(v) for v in placemark.find("kml:Point/kml:coordinates", ns).text.split(",")]
            checks.check(abs(coordinates[0] - lon) < 1e-7 and abs(coordinates[1] - lat) < 1e-7, f"{at}: at GDAL's GeoJSON position")
            for name in ("wpml:waypointHeadingParam", "wpml:waypointTurnParam"):
                if placemark.find(name, ns) is not None:
                    check_wpml_element(checks, placemark.find(name, ns), name, root, f"{at} {name}")
            functions = []
            for group in placemark.findall("wpml:actionGroup", ns):
                check_wpml_element(checks, group, "wpml:actionGroup", root, f"{at} actionGroup")
                check_wpml_element(checks, group.find("wpml:actionTrigger", ns), "wpml:actionTrigger", root, f"{at} actionTrigger")
                for action in group.findall("wpml:action", ns):
                    check_wpml_element(checks, action, "wpml:action", root, f"{at} action")
                    function = wpml_text(action, "wpml:actionActuatorFunc")
                    functions.append((function, action))
                    if "action:" + function in WPML["parents"]:
                        check_wpml_element(checks, action.find("wpml:actionActuatorFuncParam", ns), "action:" + function, root,
                                           f"{at} {function}")
            if properties.get("contact_reading"):
                checks.check("takePhoto" not in [f for f, _ in functions], f"{at}: a contact reading takes no photo")
                hovers = [float(wpml_text(a.find("wpml:actionActuatorFuncParam", ns), "wpml:hoverTime"))
                          for f, a in functions if f == "hover"]
                checks.check(hovers and abs(hovers[0] - properties["hold_s"]) < 1e-3, f"{at}: a contact reading hovers its dwell")


def check_mode_directory(checks, directory, autopilot, expect_kmz):
    tour = json.load(open(os.path.join(directory, "tour.json")))
    sorties = tour["sorties"]
    points = route_points(os.path.join(directory, "routes.geojson"))
    check_geo(checks, directory, tour)
    for k, sortie in enumerate(sorties, start=1):
        waypoints = points.get(k, [])
        plan = sortie_file(directory, "mission.plan", k, len(sorties))
        items = check_plan(checks, plan, autopilot, waypoints, sortie)
        check_wpl(checks, sortie_file(directory, "mission.waypoints", k, len(sorties)), items, autopilot)
        kmz = sortie_file(directory, "mission.kmz", k, len(sorties))
        if expect_kmz:
            checks.check(os.path.exists(kmz) and tour["dji_kmz"] == "written", f"{kmz}: written ({tour['dji_kmz']})")
        if os.path.exists(kmz):
            check_kmz(checks, kmz, waypoints)
    visited = sum(len(s["targets"]) for s in sorties)
    counted = [tour.get(key) for key in ("targets_visited", "contact_readings_taken", "photos_taken")]
    checks.check(None not in counted and sum(counted) == visited,
                 f"{directory}: targets, contact readings and photos counted apart ({counted} of {visited} stops)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--autopilot", choices=["px4", "ardupilot"], default="px4")
    parser.add_argument("--expect-kmz", action="store_true")
    parser.add_argument("tours", nargs="+")
    arguments = parser.parse_args()
    checks = Checks()
    print("references: " + "; ".join(r["source"] for r in (MAVLINK, QGC, WPML)))
    for tour in arguments.tours:
        modes = [tour] if os.path.exists(os.path.join(tour, "tour.json")) else [
            os.path.join(tour, m) for m in ("ceiling", "free") if os.path.isdir(os.path.join(tour, m))]
        checks.check(bool(modes), f"{tour}: a tour directory")
        for directory in modes:
            before = len(checks.failed)
            check_mode_directory(checks, directory, arguments.autopilot, arguments.expect_kmz)
            print(f"{directory}: {'ok' if len(checks.failed) == before else 'FAILED'}")
    print(f"{checks.passed} passed, {len(checks.failed)} failed")
    return 1 if checks.failed else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env bash
# Regenerates the seed corpus fuzz/corpus/<harness>/ with the project's own tools (the release
# build's build/bin/throng: assets generate, storyboard example/decode, cloth explore/compress)
# plus a few short hand-written inputs where no tool writes the format (legends, input
# scripts) and small synthetic trajectories in both text formats. Every file stays a few KB.
#   fuzz/make_corpus.sh [THRONG_BINARY]
set -euo pipefail
cd "$(dirname "$0")"
throng=$(realpath "${1:-../build/bin/throng}")
[ -x "$throng" ] || { echo "error: $throng not found: build it first (scripts/build.sh)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

reset() { rm -rf "corpus/$1"; mkdir -p "corpus/$1"; }

# BVH: the generated default clips cut to their first frames (the hierarchy is most of it).
bvh_slice() {  # FILE FRAMES OUT
  awk -v keep="$2" '
    /^MOTION/ { motion = 1; print; next }
    motion && /^Frames:/ { print "Frames: " keep; next }
    motion && /^Frame Time:/ { print; data = 1; next }
    data { if (++row > keep) exit }
    { print }' "$1" > "$3"
}
reset bvh
"$throng" assets generate --out "$work/assets" > /dev/null
bvh_slice "$work/assets/walk_slow.bvh" 3 corpus/bvh/walk_slow_3.bvh
bvh_slice "$work/assets/run_fast.bvh" 2 corpus/bvh/run_fast_2.bvh

# Storyboards: small example PNGs, and the agents JSON `storyboard decode --json` prints.
reset storyboard_png
reset storyboard_json
for spec in "1 16x16 2" "2 24x20 3" "3 12x30 1"; do
  read -r seed size groups <<< "$spec"
  png=corpus/storyboard_png/example_${seed}.png
  "$throng" storyboard example --seed "$seed" --size "$size" --groups "$groups" --out "$png" > /dev/null
  "$throng" storyboard decode "$png" --json > corpus/storyboard_json/example_${seed}.json
done

# Legends (no tool writes one): the default legend as JSON and variants of each key.
reset legend
cat > corpus/legend/default.json <<'JSON'
{"tolerance": 40,
 "states": {"stroll": [255,128,0], "hurried": [255,0,0]},
 "actions": {"walk": [0,200,0], "run": [255,255,0], "talk": [255,105,180], "jump": [255,0,0]}}
JSON
cat > corpus/legend/groups_hex.json <<'JSON'
{"tolerance": 20, "states": {"stroll": "#ff8000", "hurried": "#ff0000"},
 "groups": [{"name": "tourists", "colour": [0,0,255]}, {"name": "commuters", "colour": "#008000"},
            {"colour": [128,0,128]}]}
JSON
echo '{"actions": {"jump": "#102030"}, "groups": []}' > corpus/legend/actions_only.json

# Trajectories (the real ETH/UCY files are third-party data and stay out of the repository):
# a few people walking in each format. The first byte's digit picks the harness's variant
# (byte % 6: 0 auto, 1 auto as biwi_eth.txt, 2 auto as obsmat.txt, 3 frame-ped-x-y, 4 obsmat,
# 5 PedPy).
reset trajectories
awk 'BEGIN {
  printf "3"
  for (f = 0; f <= 200; f += 10)
    for (p = 1; p <= 3; ++p)
      if (f >= p * 20) printf "%d\t%d\t%.2f\t%.2f\n", f, p, 0.05 * f + p, 0.5 * p - 0.01 * f
}' > corpus/trajectories/frame_ped_xy.txt
awk 'BEGIN {
  printf "2"
  for (f = 0; f <= 120; f += 6)
    for (p = 1; p <= 2; ++p)
      printf "%.7e %.7e %.7e %.7e %.7e %.7e %.7e %.7e\n", f, p, 0.03 * f * p, 0, 1 - 0.02 * f, 1.2, 0, -0.5
}' > corpus/trajectories/obsmat.txt
awk 'BEGIN {
  printf "1"
  for (f = 780; f <= 900; f += 6) printf "%d %d %.3f %.3f\n", f, 7, f / 100.0, 2.5
}' > corpus/trajectories/biwi_eth.txt
awk 'BEGIN {
  printf "5# framerate: 25.0\n# id frame x/m y/m z/m\n"
  for (f = 0; f <= 100; f += 5)
    for (p = 1; p <= 2; ++p) printf "%d %d %.4f %.4f 1.7\n", p, f, 0.05 * f, p - 0.02 * f
}' > corpus/trajectories/pedpy.txt

# Walls (docs/formats.md, "Walls"; no tool writes them): each statement, a corridor and a room.
reset walls
printf '# a corridor and a box\npolyline -10 -1.5 10 -1.5\npolyline -10 1.5 10 1.5\npolygon 3 3 5 3 5 5 3 5\n' \
  > corpus/walls/corridor.txt
printf 'walkable -2 -2 0.5\n########\n#......#\n#..##..#\n#......#\n###..###\nend\npolyline 0 4 2 6 4 4 # a V\n' \
  > corpus/walls/room.txt

# Viewer input scripts: every command of docs/viewer.md.
reset input_script
printf '# orbit, zoom, fly\ndrag 900 400 1000 400 10\nscroll 2\nkey W 5\nkey SHIFT\nwait 3\n' \
  > corpus/input_script/orbit.txt
printf 'resize 640 480\nrespawn 500 circle\nrespawn 20\ndrag 10 10 300 200 4 right\nkey F12\nclose\n' \
  > corpus/input_script/respawn_resize.txt
printf 'key 1\nkey 2 2\nkey SPACE\nkey TAB\nscroll -1.5\ndrag 0 0 1 1 1 middle\nkey ESCAPE\n' \
  > corpus/input_script/keys.txt
printf 'lod off\ncache on\nrespawn 300 random\nlod ON\ncache off\nwait 2\n' \
  > corpus/input_script/switches.txt

# Cloth files: a tiny explored graph of the toy garment and its compressed database.
reset tsg
reset tsc
"$throng" cloth explore --garment toy --budget-expansions 2 --max-states 4 --quiet --out corpus/tsg/toy.tsg > /dev/null
"$throng" cloth explore --garment toy --budget-expansions 1 --max-states 2 --seed 3 --quiet --out corpus/tsg/toy_small.tsg > /dev/null
"$throng" cloth compress corpus/tsg/toy.tsg -o corpus/tsc/toy.tsc --min-ratio 0 --quiet > /dev/null
"$throng" cloth compress corpus/tsg/toy_small.tsg -o corpus/tsc/toy_small_2bases.tsc --bases 2 --min-ratio 0 --quiet > /dev/null

# Menge (the example scenes are third-party data and stay out of the repository): tiny scenes,
# behaviours, nav meshes and road maps written here. The first byte picks the reader: for
# `menge` '0' scene, '1' behaviour; for `menge_nav` '0' nav mesh, '1' road map.
reset menge
cat > corpus/menge/scene_grid.xml <<'XML'
0<?xml version="1.0"?>
<Experiment version="2.0">
  <Common time_step="0.1"/>
  <AgentProfile name="a"><Common r="0.2" pref_speed="1.3" max_neighbors="8" class="1">
    <Property name="r" dist="u" min="0.15" max="0.25" seed="2"/></Common></AgentProfile>
  <AgentProfile name="b" inherits="a"><Common class="2"/></AgentProfile>
  <AgentGroup><ProfileSelector type="const" name="a"/><StateSelector type="const" name="Walk"/>
    <Generator type="rect_grid" anchor_x="-2" anchor_y="1" offset_x="0.5" offset_y="-0.5"
               count_x="3" count_y="2" rotation="30" displace_dist="u" displace_min="0"
               displace_max="0.1"/></AgentGroup>
  <AgentGroup><ProfileSelector type="const" name="b"/><StateSelector type="const" name="Walk"/>
    <Generator type="explicit"><Agent p_x="1" p_y="2"/><Agent p_x="-1" p_y="0.5"/></Generator>
    <Generator type="hex_lattice" anchor_x="0" anchor_y="4" alignment="center" row_direction="y"
               density="2" width="3" population="7"/></AgentGroup>
  <ObstacleSet type="explicit" class="1">
    <Obstacle closed="1"><Vertex p_x="0" p_y="0"/><Vertex p_x="1" p_y="0"/>
      <Vertex p_x="1" p_y="1"/></Obstacle></ObstacleSet>
  <ObstacleSet type="nav_mesh" file_name="m.nav" class="2"/>
</Experiment>
XML
cat > corpus/menge/behavior.xml <<'XML'
1<?xml version="1.0"?>
<BFSM>
  <GoalSet id="0">
    <Goal type="point" id="0" x="1" y="2"/>
    <Goal type="AABB" id="1" min_x="-1" min_y="-1" max_x="1" max_y="1" capacity="5"/>
    <Goal type="circle" id="2" x="0" y="3" radius="0.5" weight="2"/>
    <Goal type="OBB" id="3" x="0" y="0" width="2" height="1" angle="45"/>
  </GoalSet>
  <State name="Walk" final="0"><GoalSelector type="random" goal_set="0" per_agent="1"/>
    <VelComponent type="nav_mesh" file_name="m.nav" heading_threshold="5"/></State>
  <State name="Wait"><GoalSelector type="explicit" goal_set="0" goal="1"/>
    <VelComponent type="zero"/></State>
  <State name="Stop" final="1"><GoalSelector type="mirror" mirror_x="1"/>
    <VelComponent type="road_map" file_name="map.txt"/></State>
  <Transition from="Walk" to="Wait"><Condition type="goal_reached" distance="0.2"/></Transition>
  <Transition from="Wait"><Condition type="timer" dist="u" min="1" max="2" per_agent="1"/>
    <Target type="prob"><State name="Walk" weight="1"/><State name="Stop" weight="2"/></Target>
  </Transition>
  <Transition from="Walk,Stop" to="Stop"><Condition type="auto"/></Transition>
</BFSM>
XML
reset menge_nav
cat > corpus/menge_nav/two_triangles.nav <<'NAV'
04
0 0
1 0
1 1
0 1
1
0 2 0 1
4
0 1 0 1
1 2 0 2
2 3 1 3
3 0 1 0
tris
2
0.66 0.33
3 0 1 2
0 0 0
1 0
2 0 1
0.33 0.66
3 0 2 3
0 0 0.5
1 0
2 2 3
NAV
printf '13\n2 0 0\n1 1 0\n1 0 1\n2\n0 1\n0 2\n' > corpus/menge_nav/road_map.txt

# Scene files (docs/formats.md): one of each behaviour, written by hand to stay small.
reset scene_file
cat > corpus/scene_file/groups.json <<'JSON'
{"schema": "throng.scene", "version": 1, "seed": 7,
 "groups": [{"count": 50, "clips": "walk", "centre": [-5, 0], "speed": [0.2, 0.6]},
            {"count": 20, "slow": "a.bvh", "fast": "b.bvh", "density": 0.8}],
 "speed_period": 5, "motion": {"lod": false, "cache": true, "bucket_width": 0.1},
 "camera": {"preset": "top", "path": [{"time": 0, "eye": [0, 30, -40], "target": [0, 0, 0]},
                                      {"time": 4, "eye": [40, 30, 0], "target": [0, 0, 0], "fov": 60}]},
 "output": {"size": "640x360", "fps": 25, "seconds": 4}}
JSON
cat > corpus/scene_file/circle.json <<'JSON'
{"schema": "throng.scene", "version": 1, "behaviour": "circle",
 "groups": [{"count": 30, "placement": "circle"}], "avoidance": {"policy": "published", "radius": 0.4}}
JSON
cat > corpus/scene_file/storyboard.json <<'JSON'
{"schema": "throng.scene", "version": 1, "behaviour": "storyboard",
 "storyboard": {"file": "board.png", "trajectories": "t.txt", "cell": 0.5, "step_time": 0.4},
 "capes": "cape.tsc", "camera": {"preset": "street", "eye": [1, 2, 3], "fov": 50}}
JSON

du -sh corpus/* | sed 's/^/corpus: /'

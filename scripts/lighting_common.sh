# Shared by scripts/lighting_results.sh and scripts/lighting_second_order.sh
# (source it; needs $vri and $size): lit scene variants, renders, and the
# error measures of docs/LIGHTING.md.
# A copy of the scene with its file paths made absolute, lit in `mode` (or unlit).
variant() {  # scene mode out
  /usr/bin/python3 - "$@" <<'PY'
import json, os, sys
scene, mode, out = sys.argv[1:4]
d = json.load(open(scene))
base = os.path.dirname(os.path.abspath(scene))
for key in ("volume", "transfer_function"):
    if "file" in d.get(key, {}):
        d[key]["file"] = os.path.normpath(os.path.join(base, d[key]["file"]))
light = d.setdefault("lighting", {})
light["enabled"] = mode != "unlit"
light["mode"] = "sampled" if mode == "unlit" else mode
json.dump(d, open(out, "w"))
PY
}
render() {  # scene out.npy args... -> prints seconds
  "$vri" render "$1" -o "$2" --width "$size" --height "$size" "${@:3}" 2>&1 | sed -n 's/.* in \([0-9.e-]*\) s.*/\1/p'
}
colour_err() {  # reference image: worst r, g, b RMS / max / share
  "$vri" compare "$1" "$2" --max-share 1 | awk 'NR > 1 && $1 != "a" { if ($3 > r) r = $3; if ($4 > m) m = $4; if ($2 > s) s = $2 }
                                  END { printf "%.2e | %.2e | %.1f%%", r, m, 100 * s }'
}
shading_err() {  # lit unlit lit_exact unlit_exact
  python3 - "$@" <<'PY'
import array, ast, math, sys
def load(p):
    b = open(p, 'rb').read(); n = int.from_bytes(b[8:10], 'little')
    h = ast.literal_eval(b[10:10 + n].decode()); a = array.array('f' if h['descr'][-1] == '4' else 'd')
    a.frombytes(b[10 + n:]); return a
A, B, C, D = map(load, sys.argv[1:5])
e = [(A[i] - B[i]) - (C[i] - D[i]) for i in range(len(A)) if i % 4 != 3]
print("%.2e" % math.sqrt(sum(x * x for x in e) / len(e)))
PY
}

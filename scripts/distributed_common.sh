# distributed_common.sh: sourced by distributed_bundled.sh and
# distributed_equality.sh. distributed_setup BUILD sets `vri` (BUILD/vri)
# and `tmp` (removed on exit); largest A B prints the largest difference
# between two images, as `vri compare` reports it.
distributed_setup() {
  vri=$(realpath "$1/vri")
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
}
largest() { "$vri" compare "$1" "$2" --tolerance 1 | awk 'NR > 1 {print $4}' | sort -g | tail -1; }

# Shared set-up and helpers of the integration scripts, sourced with the
# script's arguments: CASE UNIMAP_EXE SOURCE_DIR WORK_DIR. Each case gets an
# empty WORK_DIR/CASE and logs the commands it runs to out.txt there.
case_name=$1 exe=$2 src=$3 work=$4/$1
rm -rf "$work"; mkdir -p "$work"
log="$work/out.txt"
hokuyo="$src/configs/platforms/rotating_hokuyo.yaml"
fail() { echo "FAIL [$case_name]: $*"; echo "--- output:"; cat "$log"; exit 1; }
run() { "$exe" "$@" >>"$log" 2>&1; echo $?; }
expect() { grep -Eq -- "$1" "$log" || fail "expected /$1/"; }
json_number() {  # json_number FILE KEY: the number after "KEY": (top level or nested)
  sed -n "s/^ *\"$2\": \([-0-9.eE+]*\),\{0,1\}$/\1/p" "$1" | head -1; }
json_array() {  # json_array FILE KEY: the numbers of the array after "KEY":, one a line
  tr -d '\n ' < "$1" | sed -n "s/.*\"$2\":\[\([^]]*\)\].*/\1/p" | tr ',' '\n'; }
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 < b + 0) }'; }

# Sourced by the scripts that run on the GPU machine: unpacks the carried libraries
# (device_unpack.sh), puts them on the loader's path, and makes the tests' compiled-in
# source path (/work/main) point at this checkout. Sets `root`.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ ! -e /work/main/tests ]; then mkdir -p /work && ln -sfn "$root" /work/main; fi

#!/usr/bin/env bash
# GPU skinning on a lent GPU machine (issue 25, deliverable 4), in one device call.
#
# Here (a machine with the Rust toolchain), once:
#   cargo build --release -p deform --features gpu --example gpu_report
#   mkdir -p .gpu && cp target/release/examples/gpu_report .gpu/
#   mkdir -p .gpu/data/meshes/libigl && cp ../shared/data/meshes/libigl/armadillo{.obj,-weights.dmat} .gpu/data/meshes/libigl/
#   echo /.gpu/ >> .git/info/exclude
#   # the Vulkan loader, as the device README says (.gl holds its .deb files):
#   echo /.gl/ >> .git/info/exclude; mkdir -p .gl /tmp/amd64/partial
#   o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
#   apt-get $o update; (cd .gl && apt-get $o download libvulkan1)
# Then the device call: carry [".gpu", ".gl"], command `bash benches/gpu/run.sh`.
# It prints, per backend, the compute pass's device time (timestamp queries), the pose time
# with submit and wait and with read-back, for 1M vertices and 64 bones and for the armadillo,
# against the memory-bandwidth limit (H200: 4800 GB/s), and grades issue 25's targets.
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! ldconfig -p | grep -q libvulkan; then
  for f in .gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
fi
if [ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ]; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
fi
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader || true
CGA_DATA_DIR=.gpu/data .gpu/gpu_report --bandwidth "${BANDWIDTH_GBPS:-4800}"

#!/usr/bin/env bash
# Stand-in for a scheduler's submit command: run the job script Snakemake hands us (its last
# argument) in the background on this machine and print a job id, as qsub or sbatch would.
set -euo pipefail
jobscript="${!#}"
nohup bash "$jobscript" >/dev/null 2>&1 &
echo "local-$!"

#!/bin/bash
# A proxsim study as a Slurm job array (docs/studies.md "Slices and Slurm job
# arrays"): each task of the array runs one slice of the study's jobs, into a
# folder of its own; `proxsim study merge` then writes the answers, byte for
# byte those of one process. Submit from the folder the slices go into:
#
#   sbatch --array=1-3 study_array.sh STUDY.yaml SLICES_DIR
#   # when every task is done (squeue shows none left):
#   proxsim study merge SLICES_DIR/slice-* --out study-out
#
# Any --array range works (0-2, 1-3, 0-20:10): a task's slice is its
# position in the array. PROXSIM names the binary (default: proxsim on PATH).
#SBATCH --job-name=proxsim-study
#SBATCH --array=1-3
#SBATCH --cpus-per-task=1
#SBATCH --output=slurm-%A_%a.out
set -euo pipefail
study=$1
slices=$2
exec "${PROXSIM:-proxsim}" study "$study" --shard slurm --threads "${SLURM_CPUS_PER_TASK:-1}" \
  --out "$slices/slice-$SLURM_ARRAY_TASK_ID"

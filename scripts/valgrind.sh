#!/usr/bin/env bash
# Runs the C host tests/host/run_fmu.c against the normal FMU build (build/) under valgrind:
# memcheck (errors and leaks of every kind fail the run) on a 0.1 s simulation with state
# save / serialize / restore / reset, instances on threads, instantiate-free cycles with and
# without dlopen/dlclose, the simulation and the threads again in Model Exchange, and the FMI 3.0
# host tests/host/run_fmu3.c on the FMI 3.0 FMU; helgrind (data races) on instances running on 3
# threads, co-simulation and Model Exchange (FMI 2.0), co-simulation (FMI 3.0).
# Installs valgrind with apt when missing. About a minute.
set -euo pipefail
cd "$(dirname "$0")/.."

command -v valgrind >/dev/null || scripts/ensure_apt.sh valgrind
[ -f build/fmu/modelDescription.xml ] || scripts/setup.sh
fmi_include=$(sed -n 's/^FMI2_INCLUDE_DIR:PATH=//p' build/CMakeCache.txt)
cc -std=c99 -O2 -g -Wall -Wextra -Werror -I"$fmi_include" tests/host/run_fmu.c tests/host/fmu_host.c -o build/run_fmu \
   -ldl -lpthread

memcheck=(valgrind -q --error-exitcode=99 --leak-check=full --show-leak-kinds=all
          --errors-for-leak-kinds=all --track-origins=yes)
echo "valgrind: memcheck"
"${memcheck[@]}" build/run_fmu build/fmu simulate 0.1
"${memcheck[@]}" build/run_fmu build/fmu threads 2 0.005
"${memcheck[@]}" build/run_fmu build/fmu soak 30 norss
"${memcheck[@]}" build/run_fmu build/fmu soak 5 reload norss
cc -std=c99 -O2 -g -Wall -Wextra -Werror -I"$(sed -n 's/^FMI3_INCLUDE_DIR:PATH=//p' build/CMakeCache.txt)" \
   tests/host/run_fmu3.c -o build/run_fmu3 -ldl -lpthread
"${memcheck[@]}" build/run_fmu3 build/fmu_fmi3 0.01 0.001 >/dev/null
"${memcheck[@]}" build/run_fmu3 build/fmu_fmi3 0.0001 1e-6 me >/dev/null
"${memcheck[@]}" build/run_fmu build/fmu simulate 0.002 me
"${memcheck[@]}" build/run_fmu build/fmu threads 2 0.001 me
echo "valgrind: helgrind"
valgrind -q --tool=helgrind --error-exitcode=99 build/run_fmu build/fmu threads 3 0.005
valgrind -q --tool=helgrind --error-exitcode=99 build/run_fmu3 build/fmu_fmi3 0.002 0.001 threads 3
valgrind -q --tool=helgrind --error-exitcode=99 build/run_fmu build/fmu threads 3 0.001 me
echo "valgrind: all clean"

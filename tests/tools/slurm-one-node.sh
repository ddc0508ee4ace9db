#!/usr/bin/env bash
# A one-node Slurm cluster for tests, from Debian's slurm-wlm and munge, without systemd.
#
#   slurm-one-node.sh start DIR [CPUS]   writes the configuration into DIR (an empty folder), starts
#                                        munged, slurmctld and slurmd there and waits until the node
#                                        is idle; prints "SLURM_CONF=DIR/slurm.conf" (export it, then
#                                        sbatch, squeue, scancel … use this cluster)
#   slurm-one-node.sh stop DIR           stops the three daemons started in DIR (by their pid files)
#
# Runs as root (the daemons and the jobs run as root: SlurmUser=root). Every file (keys, state,
# spool, logs, sockets, pid files) is in DIR, the ports are free ones picked at start, so several
# clusters can run at once on one machine and nothing outside DIR is changed.
# CPUS (default 8) is the node's CPU count as Slurm sees it, whatever the machine has: jobs that
# ask for more cores than the machine has still start (they share the real cores).
set -euo pipefail

die() { echo "slurm-one-node: $*" >&2; exit 1; }

cmd=${1:-}
dir=${2:-}
[ -n "$cmd" ] && [ -n "$dir" ] || die "usage: $0 start DIR [CPUS] | stop DIR"

stop() {
  # Reverse order of start; each daemon by its own pid file, TERM then (after 10 s) KILL.
  local name pid i
  for name in slurmd slurmctld munged; do
    [ -f "$dir/$name.pid" ] || continue
    pid=$(cat "$dir/$name.pid" 2>/dev/null || true)
    [ -n "$pid" ] || continue
    kill -TERM "$pid" 2>/dev/null || continue
    for i in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null || true
    rm -f "$dir/$name.pid"
  done
}

free_port() {
  # A port nothing listens on (bash's /dev/tcp: a refused connection means free).
  local p i
  for i in $(seq 50); do
    p=$((20000 + RANDOM % 30000))
    if ! (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null; then echo "$p"; return; fi
  done
  die "no free port found"
}

case "$cmd" in
  stop) stop; exit 0 ;;
  start) ;;
  *) die "unknown command '$cmd': use start or stop" ;;
esac

cpus=${3:-8}
[ "$(id -u)" -eq 0 ] || die "must run as root (the daemons run as root, with their files in $dir)"
for p in munged:munge slurmctld:slurmctld slurmd:slurmd sbatch:slurm-client; do
  command -v "${p%%:*}" >/dev/null 2>&1 || [ -x "/usr/sbin/${p%%:*}" ] ||
    die "'${p%%:*}' is not installed: apt-get install -y slurm-wlm munge"
done
export PATH="$PATH:/usr/sbin"
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
# munged refuses a folder others can write to; a fresh mktemp -d folder is 0700.
chmod 0700 "$dir"
mkdir -p "$dir/state" "$dir/spool" "$dir/munge"

# munge: a fresh key, socket and logs in DIR. --force: root, and a socket outside /run/munge.
dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
chmod 0400 "$dir/munge/munge.key"
# Daemons get no terminal or pipe of the caller (a caller reading our output would wait for them).
munged --force --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
  --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munge/munged.seed" \
  </dev/null >"$dir/munged.out" 2>&1 || die "munged did not start: $(cat "$dir/munged.out" "$dir/munged.log" 2>/dev/null)"

host=$(hostname -s)
ctld_port=$(free_port)
slurmd_port=$(free_port)
[ "$slurmd_port" != "$ctld_port" ] || slurmd_port=$(free_port)
cat >"$dir/slurm.conf" <<EOF
ClusterName=grcis-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
# No cgroups, no accounting: a container or CI machine has neither.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
# Quick reactions for tests: dependencies and the queue are looked at every second, a killed
# step's processes get 5 s, finished jobs stay visible 5 minutes.
SchedulerParameters=sched_interval=1,sched_min_interval=100000,defer_batch
KillWait=5
MinJobAge=300
SlurmdParameters=config_overrides
NodeName=grcis1 NodeAddr=127.0.0.1 NodeHostname=$host CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=main Nodes=grcis1 Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
EOF
export SLURM_CONF="$dir/slurm.conf"

slurmctld -f "$SLURM_CONF" </dev/null >"$dir/slurmctld.out" 2>&1 ||
  die "slurmctld did not start: $(cat "$dir/slurmctld.out"; tail -n 20 "$dir/slurmctld.log" 2>/dev/null)"
slurmd -f "$SLURM_CONF" -N grcis1 </dev/null >"$dir/slurmd.out" 2>&1 ||
  die "slurmd did not start: $(cat "$dir/slurmd.out"; tail -n 20 "$dir/slurmd.log" 2>/dev/null)"

# Ready when the node is idle (the controller answers and the node has registered).
for i in $(seq 300); do
  state=$(sinfo -h -n grcis1 -o %T 2>/dev/null || true)
  [ "$state" = idle ] && { echo "SLURM_CONF=$SLURM_CONF"; exit 0; }
  sleep 0.1
done
echo "slurm-one-node: the node did not become idle in 30 s (state '${state:-none}'); logs in $dir" >&2
tail -n 20 "$dir/slurmctld.log" "$dir/slurmd.log" >&2 || true
stop
exit 1

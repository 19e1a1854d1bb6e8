#!/usr/bin/env bash
# A single-node Slurm cluster on localhost, everything (config, state, logs, munge key and
# socket) under one folder, for the farm test. Needs root (the daemons run as root here).
#   tests/slurm/local-cluster.sh start DIR   starts munged, slurmctld, slurmd; returns when the node is idle
#   tests/slurm/local-cluster.sh stop DIR    cancels every job, then stops the daemons by PID
# Clients then need SLURM_CONF=DIR/slurm.conf. No systemd or cgroups: proctrack/linuxproc, task/none.
set -euo pipefail
action=${1:?usage: $0 start|stop DIR}
dir=$(cd "${2:?usage: $0 start|stop DIR}" && pwd)
export SLURM_CONF=$dir/slurm.conf

start() {
    # munged refuses a socket folder that is not o+x all the way up (mktemp -d makes 0700).
    chmod 755 "$dir"
    mkdir -p "$dir/munge" "$dir/ctld" "$dir/spool"
    chmod 755 "$dir/munge"
    dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
    chmod 400 "$dir/munge/munge.key"
    munged --foreground --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/socket" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/seed" > "$dir/munge/munged.out" 2>&1 &
    echo $! > "$dir/munged.pid"
    for _ in $(seq 100); do [ -S "$dir/munge/socket" ] && break; sleep 0.05; done

    # Ports from the folder's name, so that two clusters on one machine do not collide.
    local port=$((20000 + $(cksum <<< "$dir" | cut -d' ' -f1) % 20000 / 2 * 2))
    local cpus memory
    cpus=$(slurmd -C | sed -n 's/.*CPUs=\([0-9]*\).*/\1/p')
    memory=$(slurmd -C | sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p')  # MB; jobs that ask for --mem are held to it
    # SlurmctldHost and NodeAddr name 127.0.0.1: host-name lookups can hang here.
    cat > "$SLURM_CONF" <<CONF
ClusterName=tetglow-test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/socket
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/ctld/slurmctld.pid
SlurmdPidFile=$dir/spool/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
SchedulerType=sched/builtin
# The default batch_sched_delay holds each round of batch jobs about 3 s.
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MinJobAge=600
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
    slurmctld -D -i -f "$SLURM_CONF" > "$dir/slurmctld.out" 2>&1 &
    echo $! > "$dir/slurmctld.pid"
    slurmd -D -f "$SLURM_CONF" > "$dir/slurmd.out" 2>&1 &
    echo $! > "$dir/slurmd.pid"
    for _ in $(seq 300); do
        [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && return 0
        sleep 0.1
    done
    echo "local-cluster: the node did not come up; see $dir/slurmctld.log and $dir/slurmd.log" >&2
    tail -n 5 "$dir/slurmctld.log" "$dir/slurmd.log" >&2 || true
    return 1
}

stop() {
    # slurmd leaves running jobs behind when it stops: cancel them first and let them go.
    if [ -f "$dir/slurmctld.pid" ] && kill -0 "$(cat "$dir/slurmctld.pid")" 2>/dev/null; then
        scancel --quiet --full --user="$(id -un)" 2>/dev/null || true
        for _ in $(seq 100); do [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break; sleep 0.1; done
    fi
    for daemon in slurmd slurmctld munged; do
        [ -f "$dir/$daemon.pid" ] || continue
        pid=$(cat "$dir/$daemon.pid")
        kill "$pid" 2>/dev/null || true
        for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done
        kill -0 "$pid" 2>/dev/null && kill -9 "$pid" 2>/dev/null || true
        rm -f "$dir/$daemon.pid"
    done
}

case "$action" in
    start) start ;;
    stop) stop ;;
    *) echo "usage: $0 start|stop DIR" >&2; exit 2 ;;
esac

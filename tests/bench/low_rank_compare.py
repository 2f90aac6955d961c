#!/usr/bin/python3
"""Tabulate runs of the contact benchmark with and without MUMPS block low-rank factorisation.

Usage: low_rank_compare.py REFERENCE JOB [JOB ...]

Each JOB (and REFERENCE, the full-rank run) is the stem of a run of low_rank_bench.sh:
JOB.log (fcs3d's log, ended by a "stopped:" or "done:" summary) and JOB.time (the output of
/usr/bin/time -v). For each run one Markdown row: increments done, factorisations, the
factorisation phase and its time per factorisation, MUMPS's factor entries and flops (full
rank, and with BLR the effective ones and their share), MUMPS's working memory (INFOG(22)),
the process's peak resident memory and CPU time; then how the run's increments agree with the
reference's over the increments both completed: whether every increment line has the same
limit (the R-minimum event that set its size, with its node or element) and event count,
the largest relative difference of the increment fraction r and of the time, and the
largest out-of-balance residual of each run over those increments. The benchmark's model is
symmetric about y = 0.5, so slip events come in simultaneous pairs of mirror nodes; which
of the two names the limit is decided by round-off, so a different node name with the same
event kind, count and r is counted apart (it is not a different increment).
"""
import re
import sys

INCREMENT = re.compile(r'^inc (\d+) step (\d+) time (\S+) dt (\S+) r (\S+) limit (.*?) events (\d+)'
                       r'(?: switches \d+)?(?: iterations (\d+))?(?: krylov \d+)? residual (\S+)')


def number(text):
    return float(text.replace('E', 'e'))


def read_log(job):
    increments, summary = [], {}
    for line in open(job + '.log'):
        match = INCREMENT.match(line)
        if match:
            increments.append({'time': number(match.group(3)), 'r': number(match.group(5)),
                               'limit': match.group(6).strip(), 'events': int(match.group(7)),
                               'iterations': int(match.group(8) or 0),
                               'residual': number(match.group(9))})
            continue
        match = re.match(r'^(stopped|done): (\d+) increment', line)
        if match:
            summary['outcome'], summary['increments'] = match.group(1), int(match.group(2))
        match = re.match(r'^\s+factorisation: (.*)$', line)
        if match:
            summary['factor_phase'] = seconds(match.group(1))
        match = re.match(r'^\s+linear solver: (\d+) analysis\(es\), (\d+) factorisation', line)
        if match:
            summary['analyses'], summary['factorisations'] = int(match.group(1)), int(match.group(2))
            summary['entries'] = number(re.search(r'last factor (\S+) entries', line).group(1))
            summary['flops'] = number(re.search(r'entries, (\S+) flops', line).group(1))
            summary['memory'] = re.search(r'([0-9.]+) MiB working memory', line).group(1)
            low_rank = re.search(r'block low-rank \(eps (\S+)\) on: (\S+) entries \(([0-9.]+)% of '
                                 r'full rank\), (\S+) flops \(([0-9.]+)%\)', line)
            if low_rank:
                summary['low_rank'] = low_rank.groups()
    return increments, summary


def seconds(text):
    """A format_duration text ("46.7 s", "1m 01s", "1h 02m") in seconds."""
    total = 0.0
    for value, unit in re.findall(r'([0-9.]+)\s*(h|m|s)', text):
        total += float(value) * {'h': 3600.0, 'm': 60.0, 's': 1.0}[unit]
    return total


def time_figures(job):
    """Peak resident memory [MiB] and CPU time (user + system) [s] from /usr/bin/time -v."""
    rss, cpu = float('nan'), 0.0
    for line in open(job + '.time'):
        if 'Maximum resident set size' in line:
            rss = int(line.split(':')[1]) / 1024.0
        elif 'User time' in line or 'System time' in line:
            cpu += float(line.split(':')[1])
    return rss, cpu


def limit_kind(limit):
    """The kind of R-minimum event that limited an increment, without its node or element."""
    return re.sub(r'(node|element|ip) \d+', r'\1', limit)


def agreement(reference, increments):
    common = min(len(reference), len(increments))
    pairs = list(zip(reference[:common], increments[:common]))
    same = all(limit_kind(a['limit']) == limit_kind(b['limit']) and a['events'] == b['events']
               for a, b in pairs)
    other_node = sum(a['limit'] != b['limit'] for a, b in pairs)
    r_diff = max((abs(a['r'] - b['r']) / max(abs(a['r']), 1e-300)
                  for a, b in zip(reference[:common], increments[:common])), default=0.0)
    t_diff = max((abs(a['time'] - b['time']) / max(abs(a['time']), 1e-300)
                  for a, b in zip(reference[:common], increments[:common])), default=0.0)
    residual = max((b['residual'] for b in increments[:common]), default=0.0)
    return common, same, other_node, r_diff, t_diff, residual


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    reference_job = sys.argv[1]
    reference, _ = read_log(reference_job)
    print('| run | increments | factorisations | factorisation phase [s] | per factorisation [s] | '
          'factor entries (full rank) | BLR entries | factor flops (full rank) | BLR flops | '
          'working memory [MiB] | peak RSS [MiB] | CPU [s] | agreement with full rank over the '
          'first increments |')
    print('|' + '---|' * 13)
    for job in sys.argv[2:]:
        increments, s = read_log(job)
        common, same, other_node, r_diff, t_diff, residual = agreement(reference, increments)
        per = s['factor_phase'] / s['factorisations'] if s.get('factorisations') else float('nan')
        if 'low_rank' in s:
            _, entries, entries_share, flops, flops_share = s['low_rank']
            blr_entries = '%.3g (%s %%)' % (number(entries), entries_share)
            blr_flops = '%.3g (%s %%)' % (number(flops), flops_share)
        else:
            blr_entries = blr_flops = '-'
        agree = '%d increments: %s limiting events and event counts%s, r within %.1e, time ' \
                'within %.1e, largest residual %.2e' \
                % (common, 'same' if same else 'DIFFERENT',
                   ' (%d name the other node of a simultaneous pair)' % other_node if other_node
                   else '', r_diff, t_diff, residual)
        rss, cpu = time_figures(job)
        print('| %s | %d (%s) | %d | %.1f | %.2f | %.4g | %s | %.4g | %s | %s | %.0f | %.1f | %s |'
              % (job, s['increments'], s['outcome'], s['factorisations'], s['factor_phase'], per,
                 s['entries'], blr_entries, s['flops'], blr_flops, s['memory'], rss, cpu, agree))


if __name__ == '__main__':
    main()

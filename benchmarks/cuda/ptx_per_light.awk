# Per-light PTX instruction counts: for every kernel (.entry) of a PTX file, the instructions of its
# largest loop body (from a label to a backward branch that returns to it with no `ret` between: a
# block laid out after the exit that jumps back is not a loop; branches and all, as
# compiled: one light per trip for the kernels of benchmarks/cuda/shade.cu that take the light count
# at run time). Prints "<mangled kernel name> <instructions per light>".
# Usage: awk -f ptx_per_light.awk file.ptx
function flush(   best, l, b) {
  if (name == "") return
  best = 0
  for (b = 1; b <= nbranch; b++) {
    l = label_at[branch_to[b]]
    if (l != "" && l < branch_line[b] && rets_at[branch_line[b]] == rets_at[l] && count_at[branch_line[b]] - count_at[l] > best)
      best = count_at[branch_line[b]] - count_at[l]
  }
  print name, best
  name = ""
}
/^\.(visible|weak)? *\.entry|^\.entry/ { flush(); name = $0; sub(/.*\.entry[ \t]+/, "", name); sub(/\(.*/, "", name)
  n = 0; rets = 0; nbranch = 0; delete label_at; delete count_at; delete rets_at; delete branch_to; delete branch_line; next }
name == "" { next }
/^\$[A-Za-z0-9_]+:/ { lab = $1; sub(/:$/, "", lab); label_at[lab] = NR; count_at[NR] = n; rets_at[NR] = rets; next }
/^[ \t]+(@!?%p[0-9]+[ \t]+)?[a-z][a-z0-9_.]*([ \t]|;)/ && !/^[ \t]+\/\// {
  n++
  if ($0 ~ /[ \t]ret;/) rets++
  count_at[NR] = n; rets_at[NR] = rets
  if ($0 ~ /[ \t]bra(\.uni)?[ \t]/) { t = $NF; sub(/;$/, "", t); nbranch++; branch_to[nbranch] = t; branch_line[nbranch] = NR }
}
END { flush() }

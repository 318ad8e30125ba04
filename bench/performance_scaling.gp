# docs/figures/performance_scaling.png from performance_scaling.dat (bench/run_scaling.sh):
# the simulation's CPU time and the process's peak memory against frames, one line per team size
# and routing table (solid: centroids from the diverse training set, the paper's setting; dashed:
# from the deployment's own environment), log-log, with the targets and the one peer figure there
# is for a simulation of this kind.
set terminal pngcairo size 1300,560 font "DejaVu Sans,11"
set output "docs/figures/performance_scaling.png"
set multiplot layout 1,2 title "Decentralized simulation on a synthetic trajectory (KITTI 00 tiled): Release, 2 shared cores" font ",13"
set logscale xy
set grid xtics ytics mxtics mytics lc "grey80"
set xlabel "frames (= queries)"
set format x "10^{%L}"
set format y "%g"
set xrange [3000:3000000]
dat = "docs/figures/performance_scaling.dat"
colour(r) = r == 10 ? "#1b9e77" : r == 100 ? "#d95f02" : "#7570b3"
# the rows of one routing table and team size, in the file's order of frames
rows(training, r) = sprintf("< awk '$7 == \"%s\" && $2 == %s' %s", training, r, dat)
set ylabel "CPU time of the simulation (s)"
set yrange [0.01:50000]
set key top left box opaque font ",9" spacing 0.9
plot for [r in "10 100 1000"] rows("diverse", r) using 1:4 with linespoints lw 2 pt 7 ps 1.2 lc rgb colour(r+0) title r." robots, diverse training", \
     for [r in "10 100 1000"] rows("deployment", r) using 1:4 with linespoints lw 2 dt 2 pt 5 ps 1.1 lc rgb colour(r+0) title r." robots, deployment-trained", \
     60 with lines dt 3 lw 2 lc "black" title "target at 10^6 frames: 60 s", \
     "-" using 1:2 with points pt 9 ps 1.8 lc "red" title "ns-3.37, network alone (KITTI 00, 100 robots, broadcast)"
4541 20.4
e
set key top left box opaque font ",9" spacing 0.9
set ylabel "peak memory of the process (MiB)"
set yrange [10:100000]
plot for [r in "10 100 1000"] rows("diverse", r) using 1:5 with linespoints lw 2 pt 7 ps 1.2 lc rgb colour(r+0) title r." robots, diverse training", \
     for [r in "10 100 1000"] rows("deployment", r) using 1:5 with linespoints lw 2 dt 2 pt 5 ps 1.1 lc rgb colour(r+0) title r." robots, deployment-trained", \
     4096 with lines dt 3 lw 2 lc "black" title "target: 4 GiB"
unset multiplot

# docs/figures/performance_scaling.png from performance_scaling.dat (bench/run_scaling.sh):
# simulation time (wall and CPU) and peak memory against frames, one line per team size,
# log-log, with the targets and the one peer figure there is for a simulation of this kind.
set terminal pngcairo size 1300,520 font "DejaVu Sans,11"
set output "docs/figures/performance_scaling.png"
set multiplot layout 1,2 title "Decentralized simulation on a synthetic trajectory (KITTI 00 tiled): Release, 2 shared cores" font ",13"
set logscale xy
set grid xtics ytics mxtics mytics lc "grey80"
set key bottom right box opaque
set xlabel "frames (= queries)"
set format x "10^{%L}"
set format y "%g"
set xrange [3000:2000000]
dat = "docs/figures/performance_scaling.dat"
colour(r) = r == 10 ? "#1b9e77" : r == 100 ? "#d95f02" : "#7570b3"
set ylabel "time of the simulation (s)"
set yrange [0.01:50000]
set key top right box opaque font ",9" spacing 0.9
plot for [r in "10 100 1000"] dat using 1:($2 == r+0 ? $4 : 1/0) with linespoints lw 2 pt 7 ps 1.2 lc rgb colour(r+0) title r." robots, CPU", \
     for [r in "10 100 1000"] dat using 1:($2 == r+0 ? $3 : 1/0) with linespoints lw 1 dt 2 pt 6 ps 1.0 lc rgb colour(r+0) title r." robots, wall", \
     60 with lines dt 3 lw 2 lc "black" title "target at 10^6 frames: 60 s", \
     "-" using 1:2 with points pt 5 ps 1.6 lc "red" title "ns-3.37, network alone (KITTI 00, 100 robots, broadcast)"
4541 20.4
e
set key bottom right box opaque
set ylabel "peak memory of the process (MiB)"
set yrange [10:10000]
plot for [r in "10 100 1000"] dat using 1:($2 == r+0 ? $5 : 1/0) with linespoints lw 2 pt 7 ps 1.2 lc rgb colour(r+0) title r." robots", \
     4096 with lines dt 3 lw 2 lc "black" title "target: 4 GiB"
unset multiplot

// corner_box.geo turned by 30 degrees about the x axis.
theta = Pi / 6;
Include "corner_box.geo";

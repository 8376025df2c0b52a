MODULE seam
  ! SeamStart and SeamEnd come from a welding add-in that is not given; the program hands
  ! them target literals, which must be declared as targets, not as num
  PROC main()
    SeamStart [[600, 10, 900], [0, 0.7071, 0.7071, 0], [-1, 0, -1, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], vSeam;
    SeamEnd [[0, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], vSeam;
  ENDPROC
ENDMODULE

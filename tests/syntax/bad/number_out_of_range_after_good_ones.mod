! expect: RMC104 line 6
MODULE m
  PROC p()
    x := 1E30;
    x := 1E30 + 2;
    x := 1E999;
    x := 1E999;
  ENDPROC
ENDMODULE

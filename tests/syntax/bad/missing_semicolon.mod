! expect: RMC101 line 5
MODULE m
  PROC main()
    x := 1
    y := 2;
  ENDPROC
ENDMODULE

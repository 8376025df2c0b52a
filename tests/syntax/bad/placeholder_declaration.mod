! expect: RMC106 line 3
MODULE m
  VAR num <ID>;
  PROC main()
  ENDPROC
ENDMODULE

! expect: RMC106 line 3
MODULE m
  <DDN>
  PROC main()
  ENDPROC
ENDMODULE

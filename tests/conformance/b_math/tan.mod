MODULE MainModule
  ! Tests: Tan takes its angle in degrees.
  PROC main()
    TPWrite "tan45=" \Num:=Round(Tan(45) \Dec:=4);
    TPWrite "tanm45=" \Num:=Round(Tan(-45) \Dec:=4);
    TPWrite "tan60=" \Num:=Round(Tan(60) \Dec:=4);
  ENDPROC
ENDMODULE

MODULE MainModule
  ! Tests: ACosDnum returns degrees in double precision.
  PROC main()
    VAR dnum half := -0.5;
    TPWrite "acos-0.5=" \Dnum:=RoundDnum(ACosDnum(half) \Dec:=9);
  ENDPROC
ENDMODULE

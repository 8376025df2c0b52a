MODULE MainModule
  ! Tests: TanDnum takes degrees and computes in double precision.
  PROC main()
    VAR dnum a45 := 45;
    VAR dnum a135 := 135;
    TPWrite "tan45=" \Dnum:=RoundDnum(TanDnum(a45) \Dec:=12);
    TPWrite "tan135=" \Dnum:=RoundDnum(TanDnum(a135) \Dec:=12);
  ENDPROC
ENDMODULE

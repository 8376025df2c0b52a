MODULE MainModule
  ! Tests: SinDnum takes degrees and computes in double precision.
  PROC main()
    VAR dnum a30 := 30;
    VAR dnum a270 := 270;
    TPWrite "sin30=" \Dnum:=RoundDnum(SinDnum(a30) \Dec:=12);
    TPWrite "sin270=" \Dnum:=RoundDnum(SinDnum(a270) \Dec:=12);
  ENDPROC
ENDMODULE

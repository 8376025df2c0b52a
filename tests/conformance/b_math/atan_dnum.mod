MODULE MainModule
  ! Tests: ATanDnum returns degrees in double precision.
  PROC main()
    VAR dnum one := 1;
    TPWrite "atan1=" \Dnum:=RoundDnum(ATanDnum(one) \Dec:=9);
    TPWrite "atanm1=" \Dnum:=RoundDnum(ATanDnum(-one) \Dec:=9);
  ENDPROC
ENDMODULE

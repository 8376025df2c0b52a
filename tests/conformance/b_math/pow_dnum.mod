MODULE MainModule
  ! Tests: PowDnum computes in double precision: 2^40 is exact in dnum.
  PROC main()
    VAR dnum base := 2;
    VAR dnum expo := 40;
    VAR dnum half := 0.5;
    VAR dnum nine := 9;
    TPWrite "2^40=" \Dnum:=PowDnum(base, expo);
    TPWrite "9^0.5=" \Dnum:=PowDnum(nine, half);
  ENDPROC
ENDMODULE

MODULE MainModule
  ! Tests: RoundDnum keeps double precision (10 decimals of pi) and rounds to integer without Dec.
  PROC main()
    VAR dnum val := 3.14159265358979;
    VAR dnum big := 4294967294.6;
    TPWrite "dec10=" \Dnum:=RoundDnum(val \Dec:=10);
    TPWrite "dec0=" \Dnum:=RoundDnum(val);
    TPWrite "big=" \Dnum:=RoundDnum(big);
  ENDPROC
ENDMODULE

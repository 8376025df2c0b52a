MODULE dnum_precision
  ! Tests: dnum is double precision: integers above 2^24 stay exact
  ! (16777216 + 1 = 16777217), unlike num; TPWrite \Dnum prints integral
  ! dnum values without decimals.
  PROC main()
    VAR dnum d := 16777216;
    d := d + 1;
    TPWrite "d=" \Dnum:=d;
    d := d * 1000;
    TPWrite "d*1000=" \Dnum:=d;
  ENDPROC
ENDMODULE

MODULE MainModule
  ! Tests: DnumToStr rounds a dnum to Dec decimals, keeping double precision.
  PROC main()
    VAR dnum big := 4294967295;
    VAR dnum val := 3.14159265358979;
    TPWrite DnumToStr(big, 0);
    TPWrite DnumToStr(val, 5);
    TPWrite DnumToStr(val, 10);
  ENDPROC
ENDMODULE

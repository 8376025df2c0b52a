MODULE while_with_nested_test
  ! Tests: compound statements nest: TEST inside IF inside WHILE.
  PROC main()
    VAR num n := 0;
    VAR num evens := 0;
    VAR num odds := 0;
    WHILE n < 6 DO
      n := n + 1;
      IF n <> 3 THEN
        TEST n MOD 2
        CASE 0:
          evens := evens + 1;
        DEFAULT:
          odds := odds + 1;
        ENDTEST
      ENDIF
    ENDWHILE
    TPWrite "evens=" \Num:=evens;
    TPWrite "odds=" \Num:=odds;
  ENDPROC
ENDMODULE

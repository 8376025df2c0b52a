MODULE MainModule
  ! Tests: successive TPReadNum calls consume successive answers, each after its prompt.
  PROC main()
    VAR num value;
    VAR num total := 0;
    FOR i FROM 1 TO 3 DO
      TPReadNum value, "Value " + NumToStr(i, 0) + "?";
      total := total + value;
      TPWrite "total=" \Num:=total;
    ENDFOR
  ENDPROC
ENDMODULE

MODULE LibDemo
  VAR string answer;
  VAR num total := 0;

  PROC main()
    TPWrite "fields: " \Num:=FieldCount("10;20;;abc", ";");
    TPWrite "second: " + FieldOf("10;20;;abc", ";", 2);
    TPWrite "third empty: " \Bool:=IsBlank(FieldOf("10;20;;abc", ";", 3));
    TPWrite "fourth: " + FieldOf("10;20;;abc", ";", 4);
    TPWrite "fifth: [" + FieldOf("10;20;;abc", ";", 5) + "]";
    FOR i FROM 1 TO 4 DO
      total := total + NumOr(FieldOf("10;20;;abc", ";", i), -1);
    ENDFOR
    TPWrite "total: " \Num:=total;
    TPWrite "clamp: " \Num:=Clamp(250, 0, 100);
    TPWrite "[" + Pad("7", 3) + "]";
  ENDPROC
ENDMODULE

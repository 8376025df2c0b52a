MODULE string_80_chars_allowed
  ! Tests: a string value may hold exactly 80 characters (the limit).
  PROC main()
    VAR string ten := "0123456789";
    VAR string s := "";
    FOR i FROM 1 TO 8 DO
      s := s + ten;
    ENDFOR
    TPWrite "len=" \Num:=StrLen(s);
  ENDPROC
ENDMODULE

MODULE string_81_chars_error
  ! Tests: a concatenation longer than 80 characters raises ERR_STRTOOLNG;
  ! uncaught, it stops the program with exit code 1 after earlier output.
  PROC main()
    VAR string ten := "0123456789";
    VAR string s := "";
    FOR i FROM 1 TO 8 DO
      s := s + ten;
    ENDFOR
    TPWrite "full";
    s := s + "x";
    TPWrite "not reached";
  ENDPROC
ENDMODULE

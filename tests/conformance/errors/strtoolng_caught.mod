MODULE strtoolng_caught
  ! Tests: ERR_STRTOOLNG from a too long concatenation is recoverable; the
  ! target keeps its old value.
  PROC main()
    VAR string s := "12345678901234567890123456789012345678901234567890";
    s := s + s;
    TPWrite "len=" \Num:=StrLen(s);
  ERROR
    IF ERRNO = ERR_STRTOOLNG TPWrite "too long";
    TRYNEXT;
  ENDPROC
ENDMODULE

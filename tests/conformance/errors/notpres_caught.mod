MODULE notpres_caught
  ! Tests: ERR_NOTPRES (use of an absent optional parameter) is recoverable
  ! in the routine's own ERROR handler.
  FUNC num valueOr(num fallback \num Given)
    RETURN Given;
  ERROR
    IF ERRNO = ERR_NOTPRES RETURN fallback;
  ENDFUNC
  PROC main()
    TPWrite "given=" \Num:=valueOr(1 \Given:=5);
    TPWrite "absent=" \Num:=valueOr(1);
  ENDPROC
ENDMODULE

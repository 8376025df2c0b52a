MODULE raise_user_number
  ! Tests: RAISE n with a user error number (1..90) in a routine without a
  ! handler reaches the caller's handler with ERRNO = n.
  PROC check(num v)
    IF v < 0 RAISE 5;
    TPWrite "ok " \Num:=v;
  ENDPROC
  PROC main()
    check 1;
    check -1;
    TPWrite "after";
  ERROR
    TPWrite "caught " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE

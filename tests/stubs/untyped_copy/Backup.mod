MODULE Backup
  ! Tests: a name whose type its uses do not tell (pHome and pSaved are only copied into
  ! each other) gets a comment, not a guess, and stubs exits 2 with the program's
  ! remaining error (issue 8, part B).
  PROC main()
    pSaved := pHome;
    nCopies := nCopies + 1;
  ENDPROC
ENDMODULE

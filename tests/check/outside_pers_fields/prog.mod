MODULE OutsideFields
    ! Issue 33: a PC writes a command word and its parameters separated by commas into
    ! the PERS command ("move,120.5,-3"); this task waits for the word, finds the commas
    ! with StrFind in a FOR loop and parses the fields between them (Hanoi TASK1's
    ! rDataOffset, rToolcheck). The domain of command (written from outside: no loaded
    ! write ends WaitUntil command <> "") holds a text with as many fields as the loop
    ! looks for, after the word ("move,1,1"): the parse runs and moved becomes 1. Before,
    ! every value lacked the commas, so the second StrFind started past the end of
    ! "move" (ERR_ARGVALERR) and no run reached moved := 1.
    ! (no_runtime_error stays VIOLATED, for a real reason as in outside_pers_part_prefix: a
    ! command that ends the waits without the two commas makes StrFind or StrPart raise.)
    PERS string command := "";
    VAR num found{2};
    VAR num position := 0;
    VAR num x := 0;
    VAR bool ok := FALSE;
    VAR num moved := 0;

    PROC main()
        command := "";
        WaitUntil command <> "";
        WaitUntil StrPart(command, 1, 4) = "move";
        position := 0;
        FOR i FROM 1 TO 2 DO
            position := StrFind(command, position + 1, ",");
            found{i} := position;
        ENDFOR
        ok := StrToVal(StrPart(command, found{1} + 1, found{2} - found{1} - 1), x);
        moved := 1;
    ENDPROC
ENDMODULE

MODULE DeadDataReplyDeadInLoop
    ! A server loop: the last reply is compared at the top of the loop and written at its
    ! end, so it is dead in between.  Main's ERROR handler repairs the divisor and RETRYs
    ! the division, so the reply is dead on the error's path too.  The first round starts
    ! with the initial reply "", the later ones with "r0" or "r1": a counterexample's loop
    ! must close on a state whose reply the program really holds there.
    VAR signaldi diIn;
    VAR num divisor := 1;
    VAR num value := 0;
    VAR string reply := "";
    VAR num repeats := 0;

    PROC main()
        AliasIO "DI_IN", diIn;
        WHILE TRUE DO
            IF reply = "r1" repeats := repeats + 1;
            IF repeats > 2 repeats := 0;
            divisor := diIn;
            value := 6 / divisor;
            reply := "r" + NumToStr(diIn, 0);
        ENDWHILE
    ERROR
        divisor := 1;
        RETRY;
    ENDPROC
ENDMODULE

MODULE Receiver
    ! Written for the test (issue 28): the receiver puts each job it is told of in the
    ! buffer the robot task clears.
    RECORD job
        bool ready;
        num code;
    ENDRECORD
    PERS job jobs{2} := [[FALSE, 0], [FALSE, 0]];
    VAR num code := 0;

    PROC main()
        WHILE TRUE DO
            TPReadNum code, "Job code?";
            WaitUntil jobs{1}.ready = FALSE;
            jobs{1}.code := code;
            jobs{1}.ready := TRUE;
        ENDWHILE
    ENDPROC
ENDMODULE

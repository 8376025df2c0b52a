MODULE Robot
    ! Written for the test (issue 28): the robot task runs the moves a macro names; it
    ! never writes the macro's text, which a PC fills in.
    PERS string stMacro{2} := ["", ""];
    PERS num nMacros := 0;

    PROC main()
        WHILE TRUE DO
            WaitUntil nMacros > 0;
            nMacros := 0;
        ENDWHILE
    ENDPROC
ENDMODULE

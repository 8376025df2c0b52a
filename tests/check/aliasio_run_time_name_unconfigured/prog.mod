MODULE HandSide
    ! A driver copied for two arms names its signals at run time ("hand_ready_" + side).
    ! Checked without the controller's I/O configuration, the name cannot be checked: the
    ! signal is taken as configured (a free input of the alias's kind; the verdict says so)
    ! instead of a false ERR_ALIASIO_DEF.
    VAR signaldi hand_ready;
    VAR string side := "L";
    VAR num readies := 0;

    PROC main()
        AliasIO "hand_ready_" + side, hand_ready;
        WHILE readies < 2 DO
            IF hand_ready = 1 Incr readies;
        ENDWHILE
    ENDPROC
ENDMODULE

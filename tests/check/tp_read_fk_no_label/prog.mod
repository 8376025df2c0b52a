MODULE TpReadFkNoLabel
    ! No key has a label and nothing else ends the dialog: the FlexPendant offers no
    ! key, so the program waits there for ever (ABB: execution waits until one of the
    ! activated function keys is pressed).
    VAR num key := 0;

    PROC main()
        TPReadFK key, "Waiting", stEmpty, stEmpty, stEmpty, stEmpty, stEmpty;
        key := key + 10;
    ENDPROC
ENDMODULE

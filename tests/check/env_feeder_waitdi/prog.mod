MODULE PickCellWait
    ! Waits for a part with WaitDI, grips it, releases it, again and again.
    VAR signaldi part;
    VAR signaldo grip;

    PROC main()
        AliasIO "DI_PART", part;
        AliasIO "DO_GRIP", grip;
        WHILE TRUE DO
            WaitDI part, 1;
            SetDO grip, 1;
            SetDO grip, 0;
        ENDWHILE
    ENDPROC
ENDMODULE
